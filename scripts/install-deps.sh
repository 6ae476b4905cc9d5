#!/usr/bin/env bash
# Installs the Debian 12 packages Plume needs to build, test and run headless.
# Idempotent: does nothing when everything is already installed.
set -euo pipefail

packages=(
  cmake g++ ninja-build pkg-config git
  libvtk9-dev python3-vtk9          # VTK 9.1 (X-only build) and its Python wrappers
  libosmesa6-dev libgl1-mesa-dri    # in-process OSMesa backend, llvmpipe
  xvfb xauth                        # private X server for the test suite
  nlohmann-json3-dev libcli11-dev libopenexr-dev libglm-dev
  libgtest-dev libbenchmark-dev
  libhypre-dev                      # structured multigrid-preconditioned CG (smoke solver pressure)
  libeigen3-dev                     # Eigen's IC-preconditioned CG: the pressure benchmark's peer
  ffmpeg                            # plume render --time-steps ... --video: frames assembled into a video
  clang-14 libclang-rt-14-dev libfuzzer-14-dev # fuzz targets (scripts/fuzz.sh): -fsanitize=fuzzer,address,undefined
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
