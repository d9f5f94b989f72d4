#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# Builds and tests NarrowVolume against the ParaView and VTK of newer Debian
# releases, each in a chroot made from Debian's packages:
#   trixie  (Debian 13)       ParaView 5.13 on its bundled VTK 9.3
#   sid     (Debian unstable) ParaView 6.1 on the external VTK 9.6, and the
#                             VTK-only flavour (no plugin) against libvtk9-dev
# For each release: debootstrap a minimal system under NV_RELEASES_DIR (once;
# later runs reuse it), install the packages below, bind-mount this source
# tree and ../shared read-only, configure, build and run ctest in the chroot.
# Prints one summary line per release and flavour (codename, ParaView and VTK
# versions, ctest's closing line) and exits non-zero if any failed.
#
#   scripts/test-releases.sh [--rebuild] [--fresh] [trixie] [sid]
#     --rebuild  delete the chroots and make them again (debootstrap, packages)
#     --fresh    delete the build folders in the chroots (configure from scratch)
#   NV_RELEASES_DIR   where the chroots and logs go (default /tmp/nv-releases)
#   NV_DEBIAN_MIRROR  the Debian mirror (default http://deb.debian.org/debian)
#
# Needs root (debootstrap, chroot, mount); uses sudo otherwise. Installs
# debootstrap on the host if it is missing. One release at a time. Trusts the
# host's own CA certificates in the chroots (pip behind a site proxy).
set -uo pipefail

if [ "$(id -u)" -ne 0 ]; then
  exec sudo --preserve-env=NV_RELEASES_DIR,NV_DEBIAN_MIRROR "$0" "$@"
fi

source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
top="${NV_RELEASES_DIR:-/tmp/nv-releases}"
mirror="${NV_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
logs="$top/logs"

rebuild=0
fresh=0
releases=()
for arg in "$@"; do
  case "$arg" in
    --rebuild) rebuild=1 ;;
    --fresh) fresh=1 ;;
    trixie | sid) releases+=("$arg") ;;
    -h | --help) sed -n '4,23p' "$0"; exit 0 ;;
    *) echo "test-releases: unknown argument $arg (see --help)" >&2; exit 2 ;;
  esac
done
[ ${#releases[@]} -gt 0 ] || releases=(trixie sid)

# What the build and the tests need, beyond what the packages pull in
# themselves (--no-install-recommends). ParaView's CMake config also asks for
# double-conversion in 5.13; ParaView 6.1's is on the external VTK, whose CMake
# files and headers are in libvtk9-dev, and it builds the plugin's help with
# xsltproc and Qt 6's help tools (5.13 skips that step with Qt 6). The tests
# want numpy, scipy (the scans test of PreserveOffset), pip and venv (the
# wheel that PythonPlugin installs; laspy, lazrs, pye57 for the LAZ and E57
# readers), liblzf (PCD's binary_compressed files),
# pytest (the Python API's tests), Open MPI's mpiexec, Xvfb and git. The pip
# wheel's tests against vtk from PyPI are left to the main suite (they do not
# depend on the release): NARROWVOLUME_TEST_PIP=OFF; the wheel is still built
# for the release's ParaView and its Python plugin tested (PythonPlugin).
common_packages=(ca-certificates cmake ninja-build g++ python3-dev python3-numpy python3-scipy python3-pip python3-venv python3-pytest liblzf1 libopenmpi-dev openmpi-bin xvfb git)
packages_trixie=(paraview-dev python3-paraview libdouble-conversion-dev "${common_packages[@]}")
packages_sid=(paraview-dev python3-paraview libvtk9-dev xsltproc qt6-tools-dev "${common_packages[@]}")

mkdir -p "$logs"
exec 9>"$top/lock"
if ! flock -n 9; then
  echo "test-releases: another run holds $top/lock" >&2
  exit 1
fi

log() { echo "=== test-releases: $*"; }

# run_in ROOT COMMAND: runs a shell command in the chroot with a clean
# environment (no DISPLAY: the GUI test starts its own Xvfb). git may read
# the source tree whoever owns it (safe.directory), as root does here.
run_in() {
  chroot "$1" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
    DEBIAN_FRONTEND=noninteractive GIT_CONFIG_COUNT=1 GIT_CONFIG_KEY_0=safe.directory GIT_CONFIG_VALUE_0='*' \
    bash -c "$2"
}

# The mount points at or under a folder, deepest first.
mounts_under() { findmnt -rn -o TARGET | awk -v r="$1" '$0 == r || index($0, r "/") == 1' | sort -r; }

# Stops the processes the tests left in the chroot (a client that timed out
# leaves its X server behind): every process whose root is the chroot.
release_processes() {
  local root="$1" signal pid
  for signal in TERM KILL; do
    for pid in $(ls /proc | grep -E '^[0-9]+$'); do
      if [ "$(readlink "/proc/$pid/root" 2>/dev/null)" = "$root" ]; then
        kill -s $signal "$pid" 2>/dev/null
      fi
    done
    sleep 1
  done
}

# Stops the chroot's processes, then unmounts everything under it.
release_root() {
  local root="$1" target
  release_processes "$root"
  for target in $(mounts_under "$root"); do
    umount "$target" 2>/dev/null || umount -l "$target"
  done
}

mounted_roots=()
cleanup() {
  local root
  for root in "${mounted_roots[@]}"; do
    release_root "$root"
  done
}
trap cleanup EXIT
trap 'exit 130' INT TERM

mount_root() {
  local root="$1"
  mounted_roots+=("$root")
  mount -t proc proc "$root/proc"
  mount -t sysfs sys "$root/sys"
  mount --rbind /dev "$root/dev"
  mount --make-rslave "$root/dev"
  mount -t tmpfs tmpfs "$root/dev/shm" # Open MPI's shared memory, private to the chroot
  mkdir -p "$root/nv/src" "$root/nv/shared"
  mount --bind "$source_dir" "$root/nv/src"
  mount -o remount,bind,ro "$root/nv/src"
  # The scan tests read ../shared/data/scans beside the source tree.
  if [ -d "$source_dir/../shared" ]; then
    mount --bind "$source_dir/../shared" "$root/nv/shared"
    mount -o remount,bind,ro "$root/nv/shared"
  fi
  # A git worktree keeps its repository elsewhere: mount that at the same path
  # so that git (the LicenseHeaders test) works in the chroot too.
  local git_dir
  git_dir="$(git -C "$source_dir" rev-parse --path-format=absolute --git-common-dir 2>/dev/null)"
  if [ -n "$git_dir" ] && [ -d "$git_dir" ] && [[ "$git_dir" != "$source_dir"/* ]]; then
    mkdir -p "$root$git_dir"
    mount --bind "$git_dir" "$root$git_dir"
    mount -o remount,bind,ro "$root$git_dir"
  fi
}

# make_root RELEASE ROOT: debootstrap, once (the marker says it completed).
make_root() {
  local release="$1" root="$2"
  if [ $rebuild -eq 1 ] || [ ! -f "$root/.nv-debootstrap-done" ]; then
    if [ -n "$(mounts_under "$root")" ]; then
      echo "test-releases: $root still has mounts; not deleting it" >&2
      return 1
    fi
    rm -rf --one-file-system "$root"
    if ! command -v debootstrap >/dev/null; then
      apt-get install -y -qq debootstrap >/dev/null 2>&1 ||
        { apt-get update -qq && apt-get install -y -qq debootstrap; } >/dev/null || return 1
    fi
    debootstrap --variant=minbase "$release" "$root" "$mirror" >"$logs/$release-debootstrap.log" 2>&1 || return 1
    # sid's Release file may have passed its Valid-Until on a mirror that lags.
    echo 'Acquire::Check-Valid-Until "false";' >"$root/etc/apt/apt.conf.d/99nv-valid-until"
    printf '#!/bin/sh\nexit 101\n' >"$root/usr/sbin/policy-rc.d" # no services in the chroot
    chmod +x "$root/usr/sbin/policy-rc.d"
    touch "$root/.nv-debootstrap-done"
  fi
}

# install_packages ROOT PACKAGES...: apt-get, skipped when this list is already in.
install_packages() {
  local root="$1"
  shift
  local wanted="$*"
  if [ -f "$root/nv/.packages" ] && [ "$(cat "$root/nv/.packages")" = "$wanted" ]; then
    return 0
  fi
  run_in "$root" "apt-get update -qq && apt-get install -y -qq --no-install-recommends $wanted" || return 1
  echo "$wanted" >"$root/nv/.packages"
}

# trust_host_certificates ROOT: the CA certificates the host added to its
# trust store (/usr/local/share/ca-certificates, e.g. a site's TLS proxy) are
# trusted in the chroot too, so that pip there reaches PyPI as it does on the
# host (InstallScanModules). Copied on every run; nothing when there are none.
trust_host_certificates() {
  local root="$1" dir="$1/usr/local/share/ca-certificates/nv-host"
  rm -rf "$dir"
  compgen -G "/usr/local/share/ca-certificates/*.crt" >/dev/null || return 0
  mkdir -p "$dir"
  cp /usr/local/share/ca-certificates/*.crt "$dir/"
  run_in "$root" "update-ca-certificates" >/dev/null
}

# version_of FILE: PACKAGE_VERSION in a <name>-config-version.cmake.
version_of() { sed -n 's/^set(PACKAGE_VERSION "\([^"]*\)")$/\1/p' "$1" | head -n 1; }

summary=()
failed=0
took() { printf '%d min %02d s' $(($1 / 60)) $(($1 % 60)); }

# test_flavour RELEASE ROOT NAME BUILD CMAKE_ARGS: configure, build and ctest
# in /nv/<BUILD>; appends the summary line.
test_flavour() {
  local release="$1" root="$2" name="$3" build="$4" args="$5"
  local prefix="$logs/$release-$build" start=$SECONDS line
  [ $fresh -eq 1 ] && rm -rf --one-file-system "$root/nv/$build"
  log "$name: configure and build (log: $prefix-build.log)"
  if ! run_in "$root" "cmake -S /nv/src -B /nv/$build -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DPython3_EXECUTABLE=/usr/bin/python3 -DNARROWVOLUME_TEST_PIP=OFF $args && cmake --build /nv/$build --parallel \$(nproc)" \
      >"$prefix-build.log" 2>&1; then
    tail -n 30 "$prefix-build.log"
    summary+=("$name: FAILED to build, see $prefix-build.log ($(took $((SECONDS - start))))")
    failed=1
    return
  fi
  local build_time=$((SECONDS - start))
  local cache="$root/nv/$build/CMakeCache.txt" paraview="" vtk_dir vtk
  vtk_dir="$(sed -n 's/^VTK_DIR:[A-Z]*=//p' "$cache")"
  vtk="VTK $(version_of "$root$vtk_dir/vtk-config-version.cmake")"
  if grep -q '^NARROWVOLUME_BUILD_PLUGIN:BOOL=ON' "$cache"; then
    paraview="ParaView $(version_of "$root$(sed -n 's/^ParaView_DIR:[A-Z]*=//p' "$cache")/paraview-config-version.cmake"), "
  fi
  log "$name: ctest (log: $prefix-ctest.log)"
  start=$SECONDS
  run_in "$root" "cd /nv/$build && ctest --output-on-failure --parallel \$(nproc)" >"$prefix-ctest.log" 2>&1
  local status=$?
  release_processes "$root"
  line="$(grep -E '^[0-9]+% tests passed' "$prefix-ctest.log" | tail -n 1)"
  [ -n "$line" ] || line="ctest did not finish (exit $status)"
  local skipped
  skipped="$(sed -n '/did not run:/,/^$/p' "$prefix-ctest.log" | grep -oE '[0-9]+ - [A-Za-z0-9_]+ \(Skipped\)' |
    sed 's/^[0-9]* - //; s/ (Skipped)//' | paste -sd, -)"
  [ -n "$skipped" ] && line="$line; skipped: $skipped"
  if [ $status -ne 0 ]; then
    grep -E '^[[:space:]]+[0-9]+ - ' "$prefix-ctest.log" | sed 's/^/    /'
    line="FAILED: $line"
    failed=1
  fi
  summary+=("$name ($paraview$vtk): $line (build $(took $build_time), ctest $(took $((SECONDS - start))))")
}

all_start=$SECONDS
for release in "${releases[@]}"; do
  root="$top/$release"
  release_start=$SECONDS
  release_root "$root" # what an interrupted run may have left mounted
  log "$release: chroot $root"
  if ! make_root "$release" "$root"; then
    summary+=("$release: FAILED to make the chroot, see $logs/$release-debootstrap.log")
    failed=1
    continue
  fi
  mount_root "$root"
  eval "packages=(\"\${packages_$release[@]}\")"
  log "$release: packages (log: $logs/$release-apt.log)"
  if ! install_packages "$root" "${packages[@]}" >"$logs/$release-apt.log" 2>&1; then
    tail -n 20 "$logs/$release-apt.log"
    summary+=("$release: FAILED to install packages, see $logs/$release-apt.log")
    failed=1
    release_root "$root"
    continue
  fi
  if ! trust_host_certificates "$root" >>"$logs/$release-apt.log" 2>&1; then
    summary+=("$release: FAILED to add the host's CA certificates, see $logs/$release-apt.log")
    failed=1
    release_root "$root"
    continue
  fi
  setup_time=$((SECONDS - release_start))
  case "$release" in
    trixie)
      test_flavour trixie "$root" "trixie" build "" ;;
    sid)
      test_flavour sid "$root" "sid" build ""
      test_flavour sid "$root" "sid, VTK only" build-vtk \
        "-DNARROWVOLUME_BUILD_PLUGIN=OFF -DVTK_DIR=/usr/lib/x86_64-linux-gnu/cmake/vtk-9.6" ;;
  esac
  release_root "$root"
  summary+=("  $release: $(took $((SECONDS - release_start))) in all, of which chroot and packages $(took $setup_time)")
done

echo
echo "=== test-releases summary"
for line in "${summary[@]}"; do
  echo "  $line"
done
echo "  total $(took $((SECONDS - all_start)))"
exit $failed
