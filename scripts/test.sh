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
# A third, small build compiles the core with the CUDA launcher of its
# device back end (nvcc, the CUDA runtime and CCCL 13 from PyPI, no GPU
# needed) and runs its test; NV_SKIP_CUDA=1 skips it.
#
# `./scripts/test.sh --quick`: the quick check after a change, in minutes:
# the build, then only the tests labelled "quick" (the core, the filter, the
# readers, the property table, the messages, one pip-free Python run); no
# docs, CUDA or sanitizer builds. The full script is what the README names
# and CI runs.
#
# Every stage runs even when an earlier one failed (a stage that needs a
# failed one is reported as not run), a summary of the stages is printed at
# the end, and the script fails if any stage failed.
set -uo pipefail
if [ "${1:-}" = "--quick" ]; then
  shift
  set -- -L quick "$@"
  export NV_SKIP_DOCS=1 NV_SKIP_CUDA=1 NV_SKIP_SANITIZE=1
fi
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

# run_ctest DIR [ARGS...]: ctest in DIR, its times into DIR/Testing/times.xml (JUnit),
# which the last stage reads (scripts/test-times.py).
run_ctest() {
  (cd "$1" && shift && ctest --output-on-failure --parallel "$(nproc)" --output-junit Testing/times.xml "$@")
}
# The seconds of every test of the builds that ran, slowest first, in
# build/test-times.md, and each against its labels' budget (Testing/budgets.json).
times=()
test_times() {
  /usr/bin/python3 "$source_dir/scripts/test-times.py" --out "$build_dir/test-times.md" \
    --budgets "$source_dir/Testing/budgets.json" "${times[@]}"
}

build_sanitize() {
  if [ ! -f "$sanitize_dir/CMakeCache.txt" ]; then
    CC=clang CXX=clang++ cmake -S "$source_dir" -B "$sanitize_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DNARROWVOLUME_BUILD_PLUGIN=OFF -DNARROWVOLUME_WRAP_PYTHON=OFF \
      -DNARROWVOLUME_SANITIZE=ON -DNARROWVOLUME_FUZZ=ON \
      -DVTK_DIR=/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11/vtk >/dev/null || return 1
  fi
  cmake --build "$sanitize_dir" --parallel "$(nproc)"
}
# The CUDA build (issue 41): the core and TestCoreDevice with
# NARROWVOLUME_CUDA=ON, so that a change that breaks the CUDA launcher fails
# the suite on machines without a GPU. The compiler comes from PyPI into a
# venv, major version 13 as on the GPU machine (CUDA 13.0); g++ 12 is its
# host compiler. Without a GPU the test runs the host launcher, and the
# CUDA launcher's error says it found no device.
cuda_dir="${build_dir}-cuda"
cuda_packages=('nvidia-cuda-nvcc==13.0.*' 'nvidia-cuda-runtime==13.0.*' 'nvidia-cuda-cccl==13.0.*'
  'nvidia-cuda-crt==13.0.*' 'nvidia-nvvm==13.0.*')
build_cuda() {
  local venv="$cuda_dir/nvcc-venv"
  if [ ! -x "$venv/bin/python" ]; then
    /usr/bin/python3 -m venv "$venv" || return 1
  fi
  "$venv/bin/pip" install --quiet --disable-pip-version-check "${cuda_packages[@]}" || return 1
  local cuda
  cuda="$("$venv/bin/python" -c 'import nvidia, os; print(os.path.join(list(nvidia.__path__)[0], "cu13"))')" || return 1
  # nvcc.profile links from lib64; the wheels put the libraries in lib.
  [ -e "$cuda/lib64" ] || ln -s lib "$cuda/lib64"
  if [ ! -f "$cuda_dir/CMakeCache.txt" ]; then
    cmake -S "$source_dir" -B "$cuda_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DNARROWVOLUME_BUILD_PLUGIN=OFF -DNARROWVOLUME_WRAP_PYTHON=OFF \
      -DNARROWVOLUME_CUDA=ON -DCMAKE_CUDA_COMPILER="$cuda/bin/nvcc" -DCMAKE_CUDA_HOST_COMPILER=g++ \
      -DVTK_DIR=/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11/vtk >/dev/null || return 1
  fi
  cmake --build "$cuda_dir" --parallel "$(nproc)" --target TestCoreDevice
}
cuda_ctest() { run_ctest "$cuda_dir" -R '^TestCoreDevice$'; }

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
    times+=("build=$build_dir=$build_dir/Testing/times.xml")
    if [ "${NV_SKIP_DOCS:-0}" != "1" ]; then
      stage "docs (scripts/docs.sh)" env BUILD_DIR="$build_dir" "$source_dir/scripts/docs.sh" --clean
    fi
  else
    skipped "ctest (build/)" "the build failed"
    skipped "docs (scripts/docs.sh)" "the build failed"
  fi
  if [ "${NV_SKIP_CUDA:-0}" != "1" ]; then
    if stage "CUDA build (core, nvcc 13 from PyPI)" build_cuda; then
      stage "ctest (CUDA build: TestCoreDevice)" cuda_ctest
      times+=("cuda=$cuda_dir=$cuda_dir/Testing/times.xml")
    else
      skipped "ctest (CUDA build: TestCoreDevice)" "the CUDA build failed"
    fi
  fi
  if [ "${NV_SKIP_SANITIZE:-0}" != "1" ]; then
    if stage "sanitizer build" build_sanitize; then
      stage "ctest (sanitizers and fuzzer)" sanitize_ctest
      times+=("sanitize=$sanitize_dir=$sanitize_dir/Testing/times.xml")
    else
      skipped "ctest (sanitizers and fuzzer)" "the sanitizer build failed"
    fi
    if stage "ThreadSanitizer build (the core alone)" build_tsan; then
      stage "ctest (ThreadSanitizer)" run_ctest "$tsan_dir"
      times+=("tsan=$tsan_dir=$tsan_dir/Testing/times.xml")
    else
      skipped "ctest (ThreadSanitizer)" "the ThreadSanitizer build failed"
    fi
  fi
  if [ ${#times[@]} -gt 0 ]; then
    stage "test times within their budgets (build/test-times.md)" test_times
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
