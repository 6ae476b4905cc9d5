#!/usr/bin/env bash
# Runs one command inside the ParaView root (scripts/paraview-root.sh makes
# it), with /proc, /sys, /dev, the repository and the shared data mounted at
# the same paths as on the host. The mounts live in a private mount namespace
# (unshare -m): they disappear when the command ends, nothing leaks onto the
# host, and concurrent runs do not interfere.
#
# Usage: bash scripts/paraview-chroot.sh COMMAND [ARGS...]
#   PLUME_PVROOT   the root (default: /var/cache/plume/pvroot)
#   PLUME_DATA_DIR a data folder to make visible too (default: ../shared/data beside the checkout, if present)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
pvroot="${PLUME_PVROOT:-/var/cache/plume/pvroot}"
data="${PLUME_DATA_DIR:-$root/../shared/data}"
if [ ! -d "$pvroot/usr" ]; then
  echo "paraview-chroot: no root at $pvroot (run scripts/paraview-root.sh)" >&2
  exit 2
fi
binds=("$root")
if [ -d "$data" ]; then binds+=("$(cd "$data" && pwd -P)"); fi

exec unshare --mount --propagation private -- bash -c '
  set -e
  pvroot="$1"; shift
  nb="$1"; shift
  mount -t proc proc "$pvroot/proc"
  mount --rbind /sys "$pvroot/sys"
  mount --rbind /dev "$pvroot/dev"
  for ((i = 0; i < nb; i++)); do
    mkdir -p "$pvroot$1"
    mount --rbind "$1" "$pvroot$1"
    shift
  done
  # The host /tmp: X servers listen on abstract sockets shared with the
  # host, so xvfb-run -a must see the host display locks to pick a free one.
  mount --rbind /tmp "$pvroot/tmp"
  exec chroot "$pvroot" /usr/bin/env -i HOME=/root PATH=/usr/local/bin:/usr/bin:/bin:/usr/sbin:/sbin \
    LANG=C.UTF-8 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "$@"
' _ "$pvroot" "${#binds[@]}" "${binds[@]}" "$@"
