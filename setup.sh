#!/usr/bin/env bash
# One command on a fresh Debian machine: installs the Debian packages the project needs (only the
# missing ones, so a second run is fast), configures and builds into ./build, and simulates
# bearing-sim's built-in default case (a 6308 at 2000 rpm under a radial load), printing its
# summary; the result files go to build/default-run/.
set -euo pipefail
cd "$(dirname "$0")"

packages=(
  build-essential cmake ninja-build ccache pkg-config git
  libeigen3-dev libgsl-dev libtomlplusplus-dev nlohmann-json3-dev libcli11-dev   # lumped/
  libhwy-dev                                                                     # lumped/: SIMD contact loop
  mpi-default-dev                                                                # lumped/: sweeps under mpirun (with mpi-default-bin)
  googletest libgtest-dev libgmock-dev libbenchmark-dev                          # tests/, bench/
  libdeal.ii-dev petsc-dev mpi-default-bin gmsh                                  # fem/, meshes/
  python3-matplotlib python3-numpy python3-jsonschema chromium                   # verification/: figures, report tests
  pybind11-dev python3-dev                                                       # python/: the module bearing (with python3-numpy)
  libhdf5-dev python3-h5py                                                       # sweep --save: sweep.h5 and its test
  libmatio-dev libsndfile1-dev python3-scipy                                     # measured records: .mat, .wav; scipy writes the tests' files
  clang strace                                                                   # tests/sanitize (libFuzzer, ASan), guarantee_tests (kills at each commit step)
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=""
  if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q "${missing[@]}"
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)"

echo
echo "setup: bearing-sim run --out build/default-run (built-in default case)"
./build/lumped/bearing-sim run --out build/default-run
