#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# The GPU's first run (issue 51): one script, at most 8 minutes with the
# build, that shows whether the device back end works on a machine with an
# NVIDIA GPU and how fast it is. Each step has a time cap (`timeout`): a
# step that fails or hangs is marked so in the final table and the script
# goes on to the next one. The steps:
#
#   1. the machine: the GPU (nvidia-smi), its free memory, the cores;
#   2. the CUDA compiler: $CUDACXX, else $CUDA_HOME/bin/nvcc, else nvcc on
#      PATH, else /usr/local/cuda/bin/nvcc; none: the script stops here;
#   3. the builds, side by side: the pip package with NARROWVOLUME_CUDA=ON
#      (the core and its Python binding, for the benchmarks) and the core's
#      C++ test TestCoreDevice by CMake (NARROWVOLUME_CORE_ONLY=ON
#      -DNARROWVOLUME_CUDA=ON: no VTK);
#   4. TestCoreDevice with the CUDA launcher (`TestCoreDeviceSTDThread
#      cuda`, NV_CUDA_SYNC=1: synchronised after each launch, so that a
#      failing kernel is named): the GPU's distances, band and neighbour
#      table the CPU's array for array, phi within 1e-9, the surfaces within
#      0.05 h, the whole run and its dense arrays;
#   5. compute-sanitizer memcheck (--leak-check full) and initcheck on the
#      small case (`TestCoreDeviceSTDThread cuda small`): 0 errors, 0 leaks;
#   6. benchmarks/gpu_check.py: the Table 1 spheres, a torus and the scans
#      (when ../shared/data/scans is beside the source tree) against the CPU;
#   7. the benchmarks' sphere at 512³ against the host launcher
#      (gpu_check.py --grid 512): the same band arrays, steps, triangles,
#      vertices within 0.05 h;
#   8. the stages at 1024³ and 4096³ (benchmarks/core_stages.py), the GPU
#      beside the machine's CPU threads in the same run, the GPU's context
#      and first run timed apart, the device's memory in use at the peak
#      beside the launcher's own count; 4096³ only where the GPU has
#      NV_GPU_4096_GB (default 40) GB free, the GPU's run before the CPU's;
#   9. the task's standing order, `core_stages.py --grid 1024 --threads 1 16`,
#      with what time is left.
#
# Then one table: each step, its result and seconds, and the stage table of
# 1024³ and 4096³: what a person pastes into doc/performance.md, "On a GPU",
# with the commit it names.
#
# Written for: Ubuntu 24.04, CUDA 13, CMake, ninja, Python 3.12 with pip,
# nanobind, scikit-build-core and numpy (CuPy optional: the device's memory
# through cudaMemGetInfo, else nvidia-smi), no VTK and no network: nothing
# is downloaded; the pip build runs without build isolation, in a venv that
# sees the system's packages.
#
#   ./scripts/test-gpu.sh
#   NV_GPU_WORK=/tmp/nv-gpu ./scripts/test-gpu.sh   # where it builds (default build-gpu/)
#   NV_GPU_BUDGET=600 ./scripts/test-gpu.sh         # seconds for it all (default 480)
#   NV_GPU_GRIDS="1024" NV_GPU_REPEAT=3 NV_GPU_THREADS=16 ./scripts/test-gpu.sh
#
# Without a GPU it builds and says which steps it skipped and why. Exit
# status: 0 when every step that ran passed (the timings are reported, not
# judged), 1 otherwise.
set -uo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work="${NV_GPU_WORK:-$source_dir/build-gpu}"
budget="${NV_GPU_BUDGET:-480}"
grids="${NV_GPU_GRIDS:-1024 4096}"
repeat="${NV_GPU_REPEAT:-3}"
threads="${NV_GPU_THREADS:-$(nproc)}"
jobs="${NV_GPU_JOBS:-$(nproc)}"
need_4096_gb="${NV_GPU_4096_GB:-40}"
python="${PYTHON:-python3}"
mkdir -p "$work/logs" || exit 1
log="$work/test-gpu.log"
: >"$log"
began=$SECONDS

say() { echo "=== test-gpu.sh: $*" | tee -a "$log"; }

# The final table's rows: step | result | seconds | note.
rows=()
failed=0
record() { # record STEP RESULT SECONDS NOTE
  rows+=("| $1 | $2 | $3 | $4 |")
  case "$2" in passed | skipped) ;; *) failed=1 ;; esac
}

# The seconds left, less 15 for the final table.
left() { echo $((budget - 15 - (SECONDS - began))); }

# The cap of a step: CAP seconds, or what is left of the budget.
cap_of() {
  local cap=$1 rest
  rest=$(left)
  [ "$rest" -lt "$cap" ] && cap=$rest
  echo "$cap"
}

# What an exit status means, for the table.
result_of() { # result_of STATUS CAP
  case "$1" in
    0) echo passed ;;
    124 | 137) echo "TIMED OUT (${2} s)" ;;
    *) echo "FAILED (exit $1)" ;;
  esac
}

# The steps' processes (each `timeout` leads a process group of its own):
# Ctrl-C or a TERM stops them and the script.
running=()
# shellcheck disable=SC2317 # called by the trap
stop_all() {
  local pid
  for pid in "${running[@]}"; do
    kill -TERM "$pid" 2>/dev/null
  done
  say "stopped by a signal"
  exit 130
}
trap stop_all INT TERM

# step NAME CAP SHOW COMMAND...: runs COMMAND under `timeout` with at most
# CAP seconds (less when the budget has less), its output into
# logs/NAME.log (and on the screen with SHOW=1), and records the result
# with STEP_NOTE. Skipped, with a line, when less than 10 s of the budget
# is left. Returns COMMAND's status.
step() {
  local name=$1 cap show=$3 file status started pid
  cap=$(cap_of "$2")
  shift 3
  file="$work/logs/${name//[^A-Za-z0-9._-]/-}.log"
  if [ "$cap" -lt 10 ]; then
    say "$name: skipped, the ${budget} s budget is spent"
    record "$name" skipped 0 "the ${budget} s budget was spent (NV_GPU_BUDGET)"
    STEP_NOTE=""
    return 124
  fi
  say "$name (at most ${cap} s; its log: $file)"
  started=$SECONDS
  timeout --kill-after=10 "$cap" "$@" >"$file" 2>&1 &
  pid=$!
  running+=("$pid")
  if [ "$show" = 1 ]; then
    tail -n +1 -s 0.2 -f --pid="$pid" "$file"
  fi
  wait "$pid"
  status=$?
  running=()
  cat "$file" >>"$log"
  local result
  result=$(result_of "$status" "$cap")
  if [ "$status" -ne 0 ]; then
    [ "$show" = 1 ] || tail -20 "$file"
    say "$name: $result"
  fi
  record "$name" "$result" $((SECONDS - started)) "${STEP_NOTE:-}"
  STEP_NOTE=""
  return "$status"
}
STEP_NOTE=""

skip() { # skip NAME WHY
  say "$1: skipped, $2"
  record "$1" skipped 0 "$2"
}

# --- 1. The machine.
say "the machine"
gpu=""
gpu_free_mb=0
arch="${CMAKE_CUDA_ARCHITECTURES:-}"
if command -v nvidia-smi >/dev/null; then
  query=$(timeout 30 nvidia-smi --query-gpu=name,memory.total,memory.free,driver_version,compute_cap \
    --format=csv,noheader,nounits 2>&1 | head -1)
  if [ -n "$query" ] && [[ "$query" != *"NVIDIA-SMI has failed"* ]] && [[ "$query" != *"No devices"* ]] &&
    [ "$(echo "$query" | awk -F', ' '{print NF}')" -ge 5 ]; then
    IFS=',' read -r gpu total_mb gpu_free_mb driver capability <<<"$query"
    gpu=$(echo "$gpu" | xargs)
    gpu_free_mb=$(echo "$gpu_free_mb" | xargs)
    gpu_free_mb=${gpu_free_mb%%.*}
    [[ "$gpu_free_mb" =~ ^[0-9]+$ ]] || gpu_free_mb=0
    capability=$(echo "$capability" | xargs)
    [ -z "$arch" ] && [[ "$capability" =~ ^[0-9]+\.[0-9]+$ ]] && arch="${capability/./}"
    say "GPU: $gpu, $(echo "$total_mb" | xargs) MiB ($gpu_free_mb free), driver $(echo "$driver" | xargs), compute capability $capability"
  else
    say "no GPU: nvidia-smi says: ${query:-nothing}"
  fi
else
  say "no GPU: no nvidia-smi on PATH (no NVIDIA driver here)"
fi
[ -z "$arch" ] && arch=90 # H100 and H200, the project's default
say "$(nproc) cores, $(free -g 2>/dev/null | awk '/^Mem:/ {print $2 " GB"}') memory; the CUDA architecture built: $arch"
commit=$(git -C "$source_dir" rev-parse --short HEAD 2>/dev/null || echo "unknown")
if [ -n "$(git -C "$source_dir" status --porcelain 2>/dev/null)" ]; then
  commit="$commit (with changes not committed)"
fi
say "the source: $source_dir at commit $commit"
if [ -n "$gpu" ]; then
  record "the machine" passed 0 "$gpu, $gpu_free_mb MiB free; $(nproc) cores"
else
  record "the machine" skipped 0 "no GPU found: the GPU's steps are skipped; $(nproc) cores"
fi

# --- 2. The CUDA compiler: CUDACXX, CUDA_HOME, PATH, /usr/local/cuda.
nvcc=""
looked=()
if [ -n "${CUDACXX:-}" ]; then
  looked+=("CUDACXX=$CUDACXX (not an executable)")
  [ -x "$CUDACXX" ] && nvcc="$CUDACXX"
fi
if [ -z "$nvcc" ] && [ -n "${CUDA_HOME:-}" ]; then
  looked+=("\$CUDA_HOME/bin/nvcc ($CUDA_HOME/bin/nvcc: none)")
  [ -x "$CUDA_HOME/bin/nvcc" ] && nvcc="$CUDA_HOME/bin/nvcc"
fi
if [ -z "$nvcc" ]; then
  looked+=("nvcc on PATH (none)")
  nvcc=$(command -v nvcc || true)
fi
if [ -z "$nvcc" ]; then
  looked+=("/usr/local/cuda/bin/nvcc (none)")
  [ -x /usr/local/cuda/bin/nvcc ] && nvcc=/usr/local/cuda/bin/nvcc
fi
if [ -z "$nvcc" ] || ! version=$(timeout 60 "$nvcc" --version 2>&1); then
  if [ -n "$nvcc" ]; then
    say "FAILED: $nvcc --version: $version"
    record "the CUDA compiler" FAILED 0 "$nvcc does not run"
  else
    looked_at=$(printf '%s; ' "${looked[@]}")
    say "FAILED: no CUDA compiler: ${looked_at%; }"
    say "set CUDACXX=/path/to/nvcc or CUDA_HOME=/path/to/cuda (CUDA 13's nvcc); nothing else can run without it"
    record "the CUDA compiler" FAILED 0 "none: ${looked_at%; }"
  fi
  echo
  echo "| step | result | seconds | note |"
  echo "|---|---|---|---|"
  printf '%s\n' "${rows[@]}"
  exit 1
fi
export CUDACXX="$nvcc"
cuda_bin=$(dirname "$nvcc")
say "the CUDA compiler: $nvcc ($(echo "$version" | grep -o 'release [0-9.]*' | head -1))"
record "the CUDA compiler" passed 0 "$nvcc, $(echo "$version" | grep -o 'release [0-9.]*' | head -1)"
sanitizer=""
for candidate in "$cuda_bin/compute-sanitizer" "$cuda_bin/../compute-sanitizer/compute-sanitizer" \
  "$(command -v compute-sanitizer || true)"; do
  if [ -n "$candidate" ] && [ -x "$candidate" ]; then
    sanitizer=$candidate
    break
  fi
done
{ cmake --version | head -1; ninja --version; "$python" --version; } 2>&1 | tee -a "$log"

# --- 3. The builds, side by side, each capped.
venv="$work/venv"
core_build="$work/core"
# shellcheck disable=SC2317 # called through bash -c below
build_pip() {
  if [ ! -x "$venv/bin/python" ]; then
    # Without pip of its own: the system's pip, nanobind, scikit-build-core
    # and numpy are seen through --system-site-packages.
    "$python" -m venv --without-pip --system-site-packages "$venv" || return 1
  fi
  "$venv/bin/python" -c "import pip, nanobind, scikit_build_core, numpy" || {
    echo "test-gpu.sh: $python lacks pip, nanobind, scikit-build-core or numpy (PYTHON=... picks another Python)"
    return 1
  }
  CMAKE_BUILD_PARALLEL_LEVEL=$jobs "$venv/bin/python" -m pip install --no-build-isolation --no-deps --no-index \
    --force-reinstall --config-settings=cmake.define.NARROWVOLUME_CUDA=ON \
    --config-settings=cmake.define.CMAKE_CUDA_ARCHITECTURES="$arch" \
    --config-settings=cmake.define.CMAKE_CUDA_COMPILER="$nvcc" \
    --config-settings=build-dir="$work/pip-build" --config-settings=cmake.build-type=Release "$source_dir"
}
# shellcheck disable=SC2317 # called through bash -c below
build_core() {
  cmake -S "$source_dir" -B "$core_build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DNARROWVOLUME_CORE_ONLY=ON \
    -DBUILD_TESTING=ON -DNARROWVOLUME_CUDA=ON -DCMAKE_CUDA_COMPILER="$nvcc" -DCMAKE_CUDA_ARCHITECTURES="$arch" &&
    cmake --build "$core_build" --target TestCoreDeviceSTDThread --parallel "$jobs"
}
build_cap=$(cap_of "${NV_GPU_BUILD_SECONDS:-240}")
say "the builds, side by side (at most ${build_cap} s each; logs: $work/logs/build-*.log)"
started=$SECONDS
# Each writes its seconds where it ends (none when it is stopped: the cap).
rm -f "$work/logs/build-pip.seconds" "$work/logs/build-core.seconds"
timeout --kill-after=10 "$build_cap" bash -c "$(declare -f build_pip); $(declare -p venv work python jobs arch nvcc source_dir)
  build_pip; status=\$?; echo \$SECONDS >'$work/logs/build-pip.seconds'; exit \$status" >"$work/logs/build-pip.log" 2>&1 &
pip_job=$!
running+=("$pip_job")
timeout --kill-after=10 "$build_cap" bash -c "$(declare -f build_core); $(declare -p core_build jobs arch nvcc source_dir)
  build_core; status=\$?; echo \$SECONDS >'$work/logs/build-core.seconds'; exit \$status" >"$work/logs/build-core.log" 2>&1 &
core_job=$!
running+=("$core_job")
wait "$pip_job"
pip_status=$?
wait "$core_job"
core_status=$?
running=()
cat "$work/logs/build-pip.log" "$work/logs/build-core.log" >>"$log"
for which in pip core; do
  if [ "$which" = pip ]; then status=$pip_status; else status=$core_status; fi
  result=$(result_of "$status" "$build_cap")
  took=$(cat "$work/logs/build-$which.seconds" 2>/dev/null || echo "$build_cap")
  if [ "$status" -ne 0 ]; then
    tail -15 "$work/logs/build-$which.log"
    say "the $which build: $result (its log: $work/logs/build-$which.log)"
  fi
  if [ "$which" = pip ]; then
    record "build: pip package, NARROWVOLUME_CUDA=ON" "$result" "$took" "the core and its binding, sm_$arch"
  else
    record "build: TestCoreDevice, NARROWVOLUME_CORE_ONLY=ON NARROWVOLUME_CUDA=ON" "$result" "$took" "no VTK"
  fi
done
say "built in $((SECONDS - started)) s"
test_device=$(find "$core_build" -name TestCoreDeviceSTDThread -type f -perm -u+x 2>/dev/null | head -1)

# --- 4. TestCoreDevice with the CUDA launcher, launches synchronised.
if [ -z "$gpu" ]; then
  skip "TestCoreDevice cuda" "no GPU"
elif [ "$core_status" -ne 0 ] || [ -z "$test_device" ]; then
  skip "TestCoreDevice cuda" "its build failed"
else
  STEP_NOTE="NV_CUDA_SYNC=1: the distances, band and neighbours array for array, phi within 1e-9, surfaces within 0.05 h"
  NV_CUDA_SYNC=1 step "TestCoreDevice cuda" 90 1 "$test_device" cuda
fi

# --- 5. compute-sanitizer on the small case: 0 errors, 0 leaks.
for tool in memcheck initcheck; do
  name="compute-sanitizer $tool"
  if [ -z "$gpu" ]; then
    skip "$name" "no GPU"
  elif [ -z "$test_device" ]; then
    skip "$name" "TestCoreDevice's build failed"
  elif [ -z "$sanitizer" ]; then
    say "$name: FAILED, no compute-sanitizer beside $nvcc nor on PATH"
    record "$name" FAILED 0 "no compute-sanitizer beside $nvcc nor on PATH"
  else
    options=(--tool "$tool" --error-exitcode 3)
    [ "$tool" = memcheck ] && options+=(--leak-check full)
    STEP_NOTE="TestCoreDeviceSTDThread cuda small; 0 errors required"
    if step "$name" 75 0 "$sanitizer" "${options[@]}" "$test_device" cuda small; then
      summary=$(grep -h "ERROR SUMMARY" "$work/logs/${name//[^A-Za-z0-9._-]/-}.log" | tail -1)
      say "$name: ${summary:-no ERROR SUMMARY line}"
      if [[ "$summary" != *"ERROR SUMMARY: 0 errors"* ]]; then
        rows[${#rows[@]} - 1]="| $name | FAILED | | ${summary:-no ERROR SUMMARY line} |"
        failed=1
      fi
    fi
  fi
done

# --- 6. and 7. The surfaces against the CPU's and the host launcher's.
benchmarks="$source_dir/benchmarks"
check() { # check NAME CAP NOTE ARGUMENTS...
  local name=$1 cap=$2
  STEP_NOTE=$3
  shift 3
  if [ -z "$gpu" ]; then
    skip "$name" "no GPU"
  elif [ "$pip_status" -ne 0 ]; then
    skip "$name" "the pip build failed"
  else
    step "$name" "$cap" 1 "$venv/bin/python" "$benchmarks/gpu_check.py" --device gpu "$@"
  fi
}
check "gpu_check.py" 75 "the Table 1 spheres, a torus, the scans if beside the source: the GPU against the CPU"
check "gpu_check.py --grid 512" 60 "the band arrays, steps and triangles the host launcher's, vertices within 0.05 h" \
  --grid 512 --reference gpu-host

# --- 8. The stages, the GPU beside the CPU's threads.
tables=()
for grid in $grids; do
  name="core_stages.py --grid $grid"
  if [ -z "$gpu" ]; then
    skip "$name" "no GPU"
    continue
  elif [ "$pip_status" -ne 0 ]; then
    skip "$name" "the pip build failed"
    continue
  fi
  runs=$repeat
  if [ "$grid" -ge 4096 ]; then
    runs=1
    if [ "$gpu_free_mb" -lt $((need_4096_gb * 1024)) ]; then
      skip "$name" "the GPU has $gpu_free_mb MiB free, less than ${need_4096_gb} GB (NV_GPU_4096_GB)"
      continue
    fi
  fi
  cap=$(cap_of $((grid >= 4096 ? 120 : 75)))
  out="$work/core_stages_${grid}.json"
  rm -f "$out"
  STEP_NOTE="$runs run(s) each, the GPU and the CPU with $threads threads"
  # Its own timeout a little earlier than the step's: the runs done are kept.
  step "$name" "$cap" 1 "$venv/bin/python" "$benchmarks/core_stages.py" --grid "$grid" --threads "$threads" \
    --device cpu gpu --repeat "$runs" --json "$out" --timeout $((cap > 30 ? cap - 15 : cap / 2))
  [ -s "$out" ] && tables+=("$out")
done

# --- 9. The standing order: the CPU's stages on 1 and 16 threads at 1024³.
if [ "$pip_status" -ne 0 ]; then
  skip "core_stages.py --grid 1024 --threads 1 16" "the pip build failed"
else
  cap=$(cap_of 60)
  STEP_NOTE="the CPU only, 1 run each"
  step "core_stages.py --grid 1024 --threads 1 16" "$cap" 1 "$venv/bin/python" "$benchmarks/core_stages.py" \
    --grid 1024 --threads 1 16 --repeat 1 --json "$work/core_stages_cpu.json" --timeout $((cap > 30 ? cap - 10 : cap / 2))
fi

# --- The table.
echo
say "the table (for doc/performance.md, \"On a GPU\")"
echo
echo "Commit $commit, $(date -u +%Y-%m-%d); ${gpu:-no GPU}, CUDA $(echo "$version" | grep -o 'release [0-9.]*' | head -1 | cut -d' ' -f2), $(nproc) cores; the script took $((SECONDS - began)) s."
echo
echo "| step | result | seconds | note |"
echo "|---|---|---|---|"
printf '%s\n' "${rows[@]}"
if [ ${#tables[@]} -gt 0 ]; then
  echo
  timeout 60 "$venv/bin/python" "$benchmarks/core_stages.py" --table "${tables[@]}"
fi
echo
echo "(the whole log: $log; each step's: $work/logs)"
exit "$failed"
