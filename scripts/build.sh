#!/usr/bin/env bash
# Configures and builds Plume into ${PLUME_BUILD_DIR:-build} (Release, Ninja).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PLUME_BUILD_DIR:-$root/build}"
bash "$root/scripts/install-deps.sh"
# /usr/bin/python3 is the interpreter that imports Debian's vtk; another python3 may come first on PATH.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPython3_EXECUTABLE=/usr/bin/python3 "$@"
cmake --build "$build" --parallel "$(nproc)"
