#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# README command 2: install what is missing, build, and run the whole test
# suite with ctest: first the full build (plugin, Python, every test), then a
# clang build of the module with AddressSanitizer, UndefinedBehaviorSanitizer
# and LeakSanitizer that runs the C++ tests and the libFuzzer target for a
# bounded time, and a third, of the core alone with ThreadSanitizer, that
# runs the core's C++ tests on the std::thread pool. Extra arguments go to the first ctest (e.g. -L cxx, -R Table1);
# NV_SKIP_SANITIZE=1 skips the second and third builds. The documentation site is built
# too (scripts/docs.sh, every warning an error); NV_SKIP_DOCS=1 skips it.
#
# Every stage runs even when an earlier one failed (a stage that needs a
# failed one is reported as not run), a summary of the stages is printed at
# the end, and the script fails if any stage failed.
set -uo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${BUILD_DIR:-$source_dir/build}"
sanitize_dir="${build_dir}-sanitize"
tsan_dir="${build_dir}-tsan"

summary=()
failed=0
# stage NAME COMMAND...: runs the command, records its outcome and duration.
stage() {
  local name="$1"
  shift
  local start=$SECONDS
  echo "=== test.sh: $name"
  "$@"
  local status=$?
  local took=$((SECONDS - start))
  if [ $status -eq 0 ]; then
    summary+=("passed   $name (${took} s)")
  else
    summary+=("FAILED   $name (exit $status, ${took} s)")
    failed=1
  fi
  return $status
}
skipped() {
  summary+=("not run  $1 ($2)")
  failed=1
}

run_ctest() { (cd "$1" && shift && ctest --output-on-failure --parallel "$(nproc)" "$@"); }

build_sanitize() {
  if [ ! -f "$sanitize_dir/CMakeCache.txt" ]; then
    CC=clang CXX=clang++ cmake -S "$source_dir" -B "$sanitize_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DNARROWVOLUME_BUILD_PLUGIN=OFF -DNARROWVOLUME_WRAP_PYTHON=OFF \
      -DNARROWVOLUME_SANITIZE=ON -DNARROWVOLUME_FUZZ=ON \
      -DVTK_DIR=/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11/vtk >/dev/null || return 1
  fi
  cmake --build "$sanitize_dir" --parallel "$(nproc)"
}
sanitize_ctest() {
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 run_ctest "$sanitize_dir"
}

build_tsan() {
  if [ ! -f "$tsan_dir/CMakeCache.txt" ]; then
    CC=clang CXX=clang++ cmake -S "$source_dir" -B "$tsan_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DNARROWVOLUME_CORE_ONLY=ON -DNARROWVOLUME_SANITIZE_THREAD=ON >/dev/null || return 1
  fi
  cmake --build "$tsan_dir" --parallel "$(nproc)"
}

if stage "install packages" "$source_dir/scripts/install-deps.sh"; then
  if stage "build" "$source_dir/scripts/build.sh"; then
    stage "ctest (build/)" run_ctest "$build_dir" "$@"
    if [ "${NV_SKIP_DOCS:-0}" != "1" ]; then
      stage "docs (scripts/docs.sh)" env BUILD_DIR="$build_dir" "$source_dir/scripts/docs.sh" --clean
    fi
  else
    skipped "ctest (build/)" "the build failed"
    skipped "docs (scripts/docs.sh)" "the build failed"
  fi
  if [ "${NV_SKIP_SANITIZE:-0}" != "1" ]; then
    if stage "sanitizer build" build_sanitize; then
      stage "ctest (sanitizers and fuzzer)" sanitize_ctest
    else
      skipped "ctest (sanitizers and fuzzer)" "the sanitizer build failed"
    fi
    if stage "ThreadSanitizer build (the core alone)" build_tsan; then
      stage "ctest (ThreadSanitizer)" run_ctest "$tsan_dir"
    else
      skipped "ctest (ThreadSanitizer)" "the ThreadSanitizer build failed"
    fi
  fi
else
  skipped "build and tests" "packages missing"
fi

echo
echo "=== test.sh summary"
for line in "${summary[@]}"; do
  echo "  $line"
done
exit $failed
