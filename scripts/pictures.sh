#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# Regenerates the documentation's pictures in doc/images/ from the scripts in
# doc/pictures/, with the build's plugin ($BUILD_DIR, default build/; run
# scripts/build.sh first), under a private Xvfb (scripts/with-xvfb.sh).
# The benchmark plot is drawn from doc/pictures/benchmark.csv; to measure
# again: pvpython doc/pictures/benchmark.py --measure (see its --help).
# The scans are read from ../shared/data/scans ($NV_SCANS_DIR); missing ones
# are skipped with a message.
set -uo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export BUILD_DIR="${BUILD_DIR:-$source_dir/build}"
cd "$source_dir"
xvfb="$source_dir/scripts/with-xvfb.sh"
failed=0
run() {
  echo "== $*"
  local start=$SECONDS
  # The filter's warnings (gaps left open, ...) are not the pictures' business.
  "$@" 2>&1 | { grep -v -E 'WARN\|' || true; }
  [ "${PIPESTATUS[0]}" -eq 0 ] || { echo "FAILED: $*"; failed=1; }
  echo "   $((SECONDS - start)) s"
}
run "$xvfb" pvpython doc/pictures/shell_cut_open.py
run "$xvfb" pvpython doc/pictures/hollow_scan.py
run "$xvfb" pvpython doc/pictures/print_part.py
run "$xvfb" pvpython doc/pictures/scan_surface.py
run "$xvfb" pvpython doc/pictures/scan_surface_open.py
run "$xvfb" pvpython doc/pictures/offset_effect.py
run "$xvfb" pvpython doc/pictures/closing_radius_effect.py
run "$xvfb" pvpython doc/pictures/parameters.py
run "$xvfb" pvpython doc/pictures/make_parameter_guide.py
run env NV_FORCE_XVFB=1 "$xvfb" /usr/bin/python3 doc/pictures/gui_panel.py
run pvpython doc/pictures/benchmark.py
exit $failed
