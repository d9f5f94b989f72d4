#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# The benchmark (benchmarks/table2.py): installs OpenVDB too, builds with the
# OpenVDB peer program, and prints the tables that doc/performance.md keeps.
# Extra arguments go to table2.py (e.g. --cases sphere dragon --repeat 5).
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${BUILD_DIR:-$source_dir/build}"
NV_EXTRA_PACKAGES="libopenvdb-dev libtbb-dev" "$source_dir/scripts/install-deps.sh"
"$source_dir/scripts/build.sh"
cmake -S "$source_dir" -B "$build_dir" -DNARROWVOLUME_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build_dir" --parallel "$(nproc)"
python="python$(/usr/bin/python3 -c 'import sys; print("%d.%d" % sys.version_info[:2])')"
PYTHONPATH="$build_dir/lib/$python/dist-packages" pvpython "$source_dir/benchmarks/table2.py" \
  --openvdb "$build_dir/bin/openvdb_shell" "$@"
