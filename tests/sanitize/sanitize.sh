#!/usr/bin/env bash
# The sanitizer stages of CI (issue 21), each a ctest test of the main build (label `sanitize`):
#
#   sanitize.sh asan SOURCE BUILD   the lumped fast set built with AddressSanitizer and
#                                   UndefinedBehaviorSanitizer (leaks included) and run
#   sanitize.sh fuzz SOURCE BUILD   each libFuzzer target of that build for BEARING_FUZZ_SECONDS
#   sanitize.sh tsan SOURCE BUILD   the sweep's thread tests built with ThreadSanitizer and run
#
# Each configuration has its own build folder (-O1 -g; only the lumped targets: no deal.II, no
# Python module, no benchmarks, no MPI, whose libraries are not instrumented and report their own
# allocations). ccache makes the second build of a configuration take seconds. A finding aborts
# the process under test (halt_on_error, -fno-sanitize-recover), which fails its test and this
# stage. With clang the ASan build is also instrumented for libFuzzer (fuzzer-no-link) and builds
# the fuzz targets; without clang the targets replay their corpus (fuzz.*.replay) and the fuzz stage
# is skipped with a message (exit 77).
set -euo pipefail
mode=${1:?mode: asan | fuzz | tsan}
src=${2:?source folder}
build=${3:?build folder}
jobs=$(nproc)

have_clang() { command -v clang++ >/dev/null && command -v clang >/dev/null; }

# Sanitizer options: stop at the first finding with a stack, and report leaks at exit.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1}

# GoogleTest's temporary folder inside the build folder: a second test run on the machine (another
# build's) never shares a file with this one.
export TEST_TMPDIR=$build/tmp/
mkdir -p "$TEST_TMPDIR"

configure() {  # configure BUILD CC CXX FLAGS [extra cmake args]
  local dir=$1 cc=$2 cxx=$3 flags=$4
  shift 4
  mkdir -p "$dir"
  if [[ ! -f $dir/CMakeCache.txt ]]; then
    CC=$cc CXX=$cxx cmake -S "$src" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Debug \
      -DCMAKE_CXX_FLAGS_DEBUG="" -DCMAKE_C_FLAGS_DEBUG="" \
      -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
      -DBEARING_WITH_FEM=OFF -DBEARING_WITH_PYTHON=OFF -DBEARING_BUILD_BENCH=OFF \
      -DCMAKE_DISABLE_FIND_PACKAGE_MPI=ON -DBEARING_SANITIZER_STAGES=OFF "$@" >"$dir.configure.log" 2>&1 ||
      { cat "$dir.configure.log"; exit 1; }
  fi
}

build_stage() {  # build_stage BUILD CTEST_ARGS...: the GoogleTest programs and what the tests name
  local dir=$1
  shift
  local listed targets
  listed=$(/usr/bin/python3 "$src/tests/sanitize/stage_targets.py" "$dir" "$@")
  mapfile -t targets <<<"$listed"
  cmake --build "$dir" -j "$jobs" --target lumped_test_programs "${targets[@]}"
}

case $mode in
  asan)
    flags="-O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all"
    if have_clang; then
      configure "$build" clang clang++ "$flags -fsanitize=fuzzer-no-link" -DBEARING_FUZZ_ENGINE=libfuzzer
    else
      echo "sanitize: clang not found (Debian: clang): ASan/UBSan with $(c++ --version | head -1), fuzz targets replay only"
      configure "$build" cc c++ "$flags"
    fi
    # The fast set: label lumped, without the FE, slow and MPI tests (see tests/CMakeLists.txt), and
    # the fuzz stage's targets (same build): only what they run is built.
    build_stage "$build" -L lumped -LE 'fem|slow|mpi'
    build_stage "$build" -L fuzz -R '\.run$'
    ctest --test-dir "$build" -L lumped -LE 'fem|slow|mpi' -j "$jobs" --output-on-failure
    ;;
  fuzz)
    if ! grep -q '^BEARING_FUZZ_ENGINE:STRING=libfuzzer' "$build/CMakeCache.txt" 2>/dev/null; then
      echo "sanitize: fuzz stage skipped: no libFuzzer build in $build (needs clang; Debian: clang)."
      echo "sanitize: the corpus and the regression inputs were replayed by fuzz.*.replay instead."
      exit 77
    fi
    # Each target fuzzes BEARING_FUZZ_SECONDS (default 60), side by side: each gets its full time
    # on the clock.
    cmake -DBEARING_FUZZ_SECONDS="${BEARING_FUZZ_SECONDS:-60}" "$build" >/dev/null
    ctest --test-dir "$build" -L fuzz -R '\.run$' -j 3 --output-on-failure
    ;;
  tsan)
    configure "$build" cc c++ "-O1 -g -fno-omit-frame-pointer -fsanitize=thread"
    cmake --build "$build" -j "$jobs" --target bearing-sim cli_tests
    # The sweep runs cases on --jobs threads (sweep.cc); these tests drive it in process and
    # through bearing-sim.
    ctest --test-dir "$build" -L lumped -LE 'fem|slow|mpi' -R 'Sweep' -j "$jobs" --output-on-failure
    ;;
  *)
    echo "sanitize.sh: mode = $mode: must be asan, fuzz or tsan" >&2
    exit 2
    ;;
esac
