#!/usr/bin/env bash
# README command 2: install what is missing, build, and run the whole test
# suite with ctest. Extra arguments go to ctest (e.g. -L cxx, -R Table1).
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${BUILD_DIR:-$source_dir/build}"
"$source_dir/scripts/install-deps.sh"
"$source_dir/scripts/build.sh"
cd "$build_dir"
ctest --output-on-failure --parallel "$(nproc)" "$@"
