#!/usr/bin/env bash
# The whole-process guard of issue 31: builds a reference commit in a worktree (ccache serves
# what did not change) and times, side by side with this checkout's build, what a user waits for:
#
#   bench/perf_guard.sh REF [BUILD]      REF: a commit (e.g. 9a8fa8f, HEAD~3); BUILD: this
#                                        checkout's build folder (default build/)
#
#   --version, the default run, the ball model run, a 4-microphone run, a 100-case sweep
#   (--jobs 1) and the Python module's import, each on one core (the guard pins itself), in
#   interleaved rounds (REF and HEAD one after another, round after round, so that load from elsewhere
#   spreads over both), ROUNDS of them (default 11) after a warm-up. Prints each as the median
#   and the spread (min–max) of both, and HEAD/REF as the ratio of the medians with the range of
#   the ratios of the rounds; also the shared libraries each bearing-sim loads.
# The worktree is PERF_GUARD_DIR/REF (default /tmp/bearing-perf-guard), kept for the next call.
# Run it on an otherwise idle machine, before resolving an issue that touches the build or the
# run path, and paste its table into the note.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "usage: bench/perf_guard.sh REF [BUILD]   (REF: a commit; BUILD default: $repo/build)" >&2
  exit 2
fi
ref=$(git -C "$repo" rev-parse --verify --quiet "$1^{commit}") || {
  echo "perf_guard.sh: REF = \"$1\": not a commit of $repo" >&2
  exit 2
}
head_build=$(cd "${2:-$repo/build}" 2>/dev/null && pwd) || {
  echo "perf_guard.sh: BUILD = \"${2:-$repo/build}\": no such folder" >&2
  exit 2
}
[[ -x $head_build/lumped/bearing-sim ]] || {
  echo "perf_guard.sh: no bearing-sim in $head_build/lumped (build it first)" >&2
  exit 2
}
short=${ref:0:10}
tree=${PERF_GUARD_DIR:-/tmp/bearing-perf-guard}/$short
if [[ ! -d $tree ]]; then
  mkdir -p "$(dirname "$tree")"
  git -C "$repo" worktree add --detach "$tree" "$ref" >/dev/null
fi
# The reference is built as a checkout of it would be (Release, Ninja); only what the timings
# run. A commit without the Python module simply has no import row.
if [[ ! -f $tree/build/build.ninja ]]; then
  cmake -S "$tree" -B "$tree/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >"$tree.configure.log" 2>&1 || {
    echo "perf_guard.sh: configuring $short failed: $tree.configure.log" >&2
    exit 1
  }
fi
targets=(bearing-sim)
# grep without -q reads the whole list: with pipefail, -q's early exit would fail ninja on SIGPIPE
# and silently leave the module out (REF's import then timed a package without it).
if ninja -C "$tree/build" -t targets all 2>/dev/null | grep '^_bearing:' >/dev/null; then
  targets+=(_bearing)
fi
echo "perf_guard.sh: building ${targets[*]} of $short in $tree/build" >&2
cmake --build "$tree/build" -j2 --target "${targets[@]}" >"$tree.build.log" 2>&1 || {
  echo "perf_guard.sh: building $short failed: $tree.build.log" >&2
  exit 1
}
exec /usr/bin/python3 "$repo/bench/perf_guard.py" --repo "$repo" --ref "$short" \
  --ref-build "$tree/build" --head-build "$head_build" --rounds "${ROUNDS:-11}"
