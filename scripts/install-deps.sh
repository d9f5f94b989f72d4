#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# Installs what NarrowVolume needs on Debian 12 (ParaView 5.11 and its headers,
# the build tools, Xvfb for the GUI test, Open MPI; pip, with which the tests
# install laspy, lazrs and pye57 for the LAZ and E57 readers, and liblzf, the
# PCD test's second LZF compressor). Idempotent: packages that
# are already installed are skipped, so a second run costs a few seconds.
set -euo pipefail

PACKAGES=(
  paraview paraview-dev python3-paraview
  cmake ninja-build g++ make
  libdouble-conversion-dev liblz4-dev libutfcpp-dev libopenmpi-dev openmpi-bin
  libexpat1-dev libfreetype-dev libglew-dev libgl2ps-dev libjpeg-dev libpng-dev
  libtiff-dev libxml2-dev zlib1g-dev libnetcdf-dev libtheora-dev libogg-dev
  libavcodec-dev libavformat-dev libswscale-dev libavutil-dev libhdf5-openmpi-dev
  python3-dev python3-numpy libeigen3-dev libx11-dev libgl-dev libboost-dev liblzma-dev
  qtbase5-dev qttools5-dev libqt5svg5-dev qttools5-dev-tools qtxmlpatterns5-dev-tools
  xvfb xauth clang libclang-rt-14-dev time
  python3-pip liblzf1
)
# Optional extras asked for by name: NV_EXTRA_PACKAGES="libopenvdb-dev libtbb-dev"
read -r -a EXTRA <<< "${NV_EXTRA_PACKAGES:-}"

missing=()
for p in "${PACKAGES[@]}" "${EXTRA[@]}"; do
  [ -n "$p" ] || continue
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: everything is installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
