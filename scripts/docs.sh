#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# Builds the documentation site (doc/, Sphinx with MyST Markdown) into
# BUILD_DIR/docs/html, every warning an error. Needs the build (it runs
# scripts/build.sh first when there is none; the Debian packages come from
# scripts/install-deps.sh, which the README's two commands run):
# the Python API reference imports the built `narrowvolume` package, which
# needs Debian's ParaView VTK, hence a virtual environment over /usr/bin/python3
# with --system-site-packages. The tools come from PyPI, pinned, once; later
# runs reuse the environment and need no network.
#
#   ./scripts/docs.sh            # then open build/docs/html/index.html
#   ./scripts/docs.sh --clean    # from an empty build/docs
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${BUILD_DIR:-$source_dir/build}"
docs_dir="$build_dir/docs"
venv="$build_dir/docs-venv"
requirements="$source_dir/doc/requirements.txt"

if [ "${1:-}" = "--clean" ]; then
  rm -rf "$docs_dir"
fi
# The built package, in the site-packages folder of ParaView's Python.
packages="$build_dir/lib/$(/usr/bin/python3 -c 'import sys; print("python%d.%d" % sys.version_info[:2])')/dist-packages"
if [ ! -d "$packages/narrowvolume" ]; then
  echo "docs.sh: no built package in $build_dir: building it (scripts/build.sh)"
  if ! BUILD_DIR="$build_dir" "$source_dir/scripts/build.sh"; then
    echo "docs.sh: the build failed; install the packages first (./scripts/install-deps.sh, or the README's commands)" >&2
    exit 1
  fi
fi
# The environment, made again when the pinned list changes.
if ! cmp -s "$requirements" "$venv/requirements.txt" 2>/dev/null; then
  rm -rf "$venv"
  /usr/bin/python3 -m venv --system-site-packages "$venv"
  "$venv/bin/python" -m pip install --quiet --disable-pip-version-check -r "$requirements"
  cp "$requirements" "$venv/requirements.txt"
fi
mkdir -p "$docs_dir"
# -W: warnings are errors; -n: every reference must resolve; --keep-going: all of them at once.
PYTHONPATH="$packages${PYTHONPATH:+:$PYTHONPATH}" \
NV_BUILD_DIR="$build_dir" \
  "$venv/bin/python" -m sphinx -W --keep-going -n -q -b html -d "$docs_dir/doctrees" \
  "$source_dir/doc" "$docs_dir/html"
# The site reads offline: no page loads a script or a stylesheet from another
# host (the equations' MathJax is in _static/mathjax, see doc/conf.py).
if remote=$(grep -rnoE '<(script|link)[^>]*(src|href)="(https?:)?//[^"]*"' --include='*.html' "$docs_dir/html"); then
  echo "docs.sh: pages load files from the network:" >&2
  echo "$remote" >&2
  exit 1
fi
if [ ! -f "$docs_dir/html/_static/mathjax/tex-chtml.js" ]; then
  echo "docs.sh: the site has no _static/mathjax/tex-chtml.js (doc/conf.py's mathjax_path)" >&2
  exit 1
fi
echo "docs.sh: the site is in $docs_dir/html (index.html)"
