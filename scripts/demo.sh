#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# README command 1: install what is missing, build, and reconstruct the demo
# point cloud (Data/trefoil.vtp) into out/: trefoil_phi.vti, trefoil_shell.vtp,
# trefoil_shell.stl and trefoil.png. Extra arguments go to examples/reconstruct.py.
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$source_dir/scripts/install-deps.sh"
"$source_dir/scripts/build.sh"
cd "$source_dir"
"$source_dir/scripts/with-xvfb.sh" pvpython "$source_dir/examples/reconstruct.py" \
  --plugin "${BUILD_DIR:-$source_dir/build}/lib/paraview-5.11/plugins/NarrowVolume/NarrowVolume.so" "$@"
