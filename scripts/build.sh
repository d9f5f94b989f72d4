#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# Configures and builds NarrowVolume (module, Python package, ParaView plugin)
# in BUILD_DIR (default: build/ in the source tree).
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${BUILD_DIR:-$source_dir/build}"
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  # ParaView's Python is Debian's /usr/bin/python3, whatever python3 is first on PATH.
  cmake -S "$source_dir" -B "$build_dir" "${generator[@]}" \
    -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 ${NV_CMAKE_ARGS:-}
fi
cmake --build "$build_dir" --parallel "$(nproc)"
