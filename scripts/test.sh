#!/usr/bin/env bash
# README command 2: install what is missing, build, and run the whole test
# suite with ctest: first the full build (plugin, Python, every test), then a
# clang build of the module with AddressSanitizer, UndefinedBehaviorSanitizer
# and LeakSanitizer that runs the C++ tests and the libFuzzer target for a
# bounded time. Extra arguments go to the first ctest (e.g. -L cxx, -R Table1);
# NV_SKIP_SANITIZE=1 skips the second build.
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${BUILD_DIR:-$source_dir/build}"
"$source_dir/scripts/install-deps.sh"
"$source_dir/scripts/build.sh"
(cd "$build_dir" && ctest --output-on-failure --parallel "$(nproc)" "$@")

if [ "${NV_SKIP_SANITIZE:-0}" != "1" ]; then
  sanitize_dir="${build_dir}-sanitize"
  if [ ! -f "$sanitize_dir/CMakeCache.txt" ]; then
    CC=clang CXX=clang++ cmake -S "$source_dir" -B "$sanitize_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DNARROWVOLUME_BUILD_PLUGIN=OFF -DNARROWVOLUME_WRAP_PYTHON=OFF \
      -DNARROWVOLUME_SANITIZE=ON -DNARROWVOLUME_FUZZ=ON \
      -DVTK_DIR=/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11/vtk >/dev/null
  fi
  cmake --build "$sanitize_dir" --parallel "$(nproc)"
  (cd "$sanitize_dir" && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --output-on-failure --parallel "$(nproc)")
fi
