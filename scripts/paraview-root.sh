#!/usr/bin/env bash
# Creates (once) and refreshes a private Debian 12 root holding ParaView 5.11
# (paraview, paraview-dev, python3-paraview) and the build tools the plugin
# needs. The plugin cannot be built on the host: python3-paraview conflicts
# with python3-vtk9, which libvtk9-dev (the VTK 9.1 build) depends on, so
# installing ParaView on the host would remove the VTK 9.1 build's packages.
# The root keeps both package states on one machine.
#
# Idempotent and cached: a root whose package set is complete is left as it is
# (a stamp file records the package list it was made with); a changed list
# installs what is missing. Needs root (debootstrap, chroot).
#
# Usage: bash scripts/paraview-root.sh           create/refresh, print the root
#   PLUME_PVROOT   where the root lives (default: /var/cache/plume/pvroot)
#   PLUME_MIRROR   Debian mirror (default: the host's deb.debian.org)
set -euo pipefail
pvroot="${PLUME_PVROOT:-/var/cache/plume/pvroot}"
mirror="${PLUME_MIRROR:-http://deb.debian.org/debian}"

packages=(
  paraview paraview-dev python3-paraview       # ParaView 5.11 and its VTK 9.2
  cmake ninja-build g++ make pkg-config        # the plugin build
  libglm-dev nlohmann-json3-dev libcli11-dev libopenexr-dev libhypre-dev libeigen3-dev
  xvfb xauth libgl1-mesa-dri                   # headless rendering (llvmpipe)
  openmpi-bin python3-numpy python3-pil        # mpirun, image comparison in the tests
  # What ParaView's CMake package finds whenever it is loaded (paraview-dev
  # does not depend on them): X11, image/compression/IO libraries, GL, MPI's
  # Python, double-conversion.
  libx11-dev libxt-dev libpng-dev libtiff-dev libjpeg-dev libfreetype-dev libexpat1-dev liblz4-dev
  liblzma-dev zlib1g-dev libxml2-dev libhdf5-dev libnetcdf-dev libtheora-dev libgl2ps-dev libglew-dev
  libgl-dev libutfcpp-dev python3-dev python3-mpi4py libdouble-conversion-dev libboost-dev
)
stamp="$pvroot/.plume-packages"
want="$(printf '%s\n' "${packages[@]}" | sort)"

log() { echo "paraview-root: $*" >&2; }
if [ "$(id -u)" -ne 0 ]; then
  log "needs root (debootstrap, chroot); run it with sudo"
  exit 2
fi

if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ]; then
  log "up to date: $pvroot"
  echo "$pvroot"
  exit 0
fi

start=$(date +%s)
if [ ! -x "$pvroot/usr/bin/apt-get" ]; then
  if ! command -v debootstrap >/dev/null; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q debootstrap
  fi
  log "debootstrap bookworm into $pvroot"
  rm -rf "$pvroot.tmp"
  mkdir -p "$(dirname "$pvroot")"
  debootstrap --variant=minbase bookworm "$pvroot.tmp" "$mirror" >&2
  mv "$pvroot.tmp" "$pvroot"
fi

# Package scripts want /proc and /dev: paraview-chroot.sh mounts them in a
# private mount namespace, gone when the command ends.
cp /etc/resolv.conf "$pvroot/etc/resolv.conf" 2>/dev/null || true
in_root() { PLUME_PVROOT="$pvroot" bash "$(dirname "${BASH_SOURCE[0]}")/paraview-chroot.sh" "$@"; }
in_root env DEBIAN_FRONTEND=noninteractive apt-get update -q >&2
in_root env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y -q --no-install-recommends "${packages[@]}" >&2
in_root apt-get clean
echo "$want" >"$stamp"
log "ready in $(($(date +%s) - start)) s: $pvroot"
echo "$pvroot"
