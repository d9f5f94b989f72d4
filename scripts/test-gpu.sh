#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# The device back end on a machine with an NVIDIA GPU (issue 41): builds the
# core with its CUDA launcher through the pip build, checks the GPU's
# surfaces against the CPU core's (benchmarks/gpu_check.py: the Table 1
# sphere at h = 0.01 and 0.005 and a torus, the band's nodes as many as the
# CPU's (the distance on the GPU is written to be the CPU's bit for bit),
# the surface made on the GPU, every vertex within 0.05 h of the CPU's, both
# sheets closed, Table 1's errors, and the torus's dense phi with the Volume
# output, filled on the GPU, within 1e-6 of the CPU's; three scans of
# ../shared/data/scans with their defaults, when that folder is beside the
# source tree (skipped with a line otherwise); the distance, band,
# evolution, surface and volume stages' seconds beside the CPU's), and
# times the stages on
# the benchmarks' sphere, the GPU beside the machine's CPU threads in the
# same run (benchmarks/core_stages.py --device cpu gpu), one table.
#
# Written for: Ubuntu 24.04, CUDA 13 with nvcc on PATH (or CUDACXX), CMake,
# ninja, Python 3.12 with nanobind, scikit-build-core and numpy installed,
# no VTK and no network. Nothing is downloaded: the pip build runs without
# build isolation and without dependencies, in a venv that sees the
# system's packages.
#
# Where the GPU stands (what this script has shown on which GPU) is written
# in one place: doc/performance.md, "On a GPU".
#
#   ./scripts/test-gpu.sh                  # the 1024³ sphere in the table
#   NV_GPU_GRIDS="512 1024 2048" ./scripts/test-gpu.sh
#   NV_GPU_WORK=/tmp/nv-gpu ./scripts/test-gpu.sh   # where it builds (default build-gpu/)
#
# Exit status: 0 when the build and the check pass (the timings are
# reported, not judged), 1 otherwise.
set -uo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work="${NV_GPU_WORK:-$source_dir/build-gpu}"
grids="${NV_GPU_GRIDS:-1024}"
threads="${NV_GPU_THREADS:-$(nproc)}"
python="${PYTHON:-python3}"
mkdir -p "$work"
log="$work/test-gpu.log"
: >"$log"
say() { echo "=== test-gpu.sh: $*" | tee -a "$log"; }
fail() { say "FAILED: $*"; exit 1; }

say "the machine"
{ nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv,noheader 2>&1 || echo "(no nvidia-smi)"; } | tee -a "$log"
command -v nvcc >/dev/null || [ -n "${CUDACXX:-}" ] || fail "no nvcc on PATH (nor CUDACXX): the CUDA launcher cannot be built"
{ ${CUDACXX:-nvcc} --version | tail -2; cmake --version | head -1; "$python" --version; echo "$(nproc) cores"; } 2>&1 | tee -a "$log"

say "build: pip install with NARROWVOLUME_CUDA=ON (the core and its binding)"
start=$SECONDS
venv="$work/venv"
if [ ! -x "$venv/bin/python" ]; then
  # Without pip of its own (no ensurepip needed): the system's pip, nanobind,
  # scikit-build-core and numpy are seen through --system-site-packages, and
  # pip run by the venv's python installs into the venv.
  "$python" -m venv --without-pip --system-site-packages "$venv" || fail "$python -m venv"
fi
"$venv/bin/python" -c "import pip, nanobind, scikit_build_core, numpy" 2>&1 | tee -a "$log" ||
  fail "$python lacks pip, nanobind, scikit-build-core or numpy (PYTHON=... picks another Python)"
# The architectures of the GPU at hand (CMake's "native"), unless given.
arch="${CMAKE_CUDA_ARCHITECTURES:-native}"
"$venv/bin/python" -m pip install --no-build-isolation --no-deps --no-index --force-reinstall \
  --config-settings=cmake.define.NARROWVOLUME_CUDA=ON --config-settings=cmake.define.CMAKE_CUDA_ARCHITECTURES="$arch" \
  --config-settings=build-dir="$work/pip-build" --config-settings=cmake.build-type=Release "$source_dir" >>"$log" 2>&1 ||
  { tail -40 "$log"; fail "the pip build (its log: $log)"; }
build_seconds=$((SECONDS - start))
say "built in ${build_seconds} s"

say "check: the GPU against the CPU core (benchmarks/gpu_check.py)"
(cd "$source_dir/benchmarks" && "$venv/bin/python" gpu_check.py --device gpu) 2>&1 | tee -a "$log"
check=${PIPESTATUS[0]}

say "benchmark: the stages, CPU ($threads threads) and GPU in one run (benchmarks/core_stages.py)"
tables=()
for grid in $grids; do
  out="$work/core_stages_${grid}.txt"
  (cd "$source_dir/benchmarks" && "$venv/bin/python" core_stages.py --grid "$grid" --threads "$threads" \
    --device cpu gpu --repeat "${NV_GPU_REPEAT:-3}") >"$out" 2>&1
  status=$?
  cat "$out" >>"$log"
  if [ $status -ne 0 ]; then
    tail -5 "$out"
    say "the benchmark at ${grid}³ failed (exit $status)"
    check=1
  fi
  tables+=("$out")
done

echo
say "summary"
echo "device: $(nvidia-smi --query-gpu=name --format=csv,noheader 2>/dev/null | head -1); $(nproc) cores; build ${build_seconds} s"
echo "check (gpu_check.py): $([ "$check" -eq 0 ] && echo PASSED || echo FAILED)"
for out in "${tables[@]}"; do
  echo
  sed -n '/³ grid/,$p' "$out"
done
echo
echo "(the whole log: $log)"
exit $((check != 0))
