#!/usr/bin/env bash
# Set-up command 2: install what is missing, build, and run the whole test
# suite headless (a private Xvfb for VTK's X-only render windows).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PLUME_BUILD_DIR:-$root/build}"
bash "$root/scripts/build.sh"
cd "$build"
xvfb-run -a -s "-screen 0 1024x768x24 -noreset" \
  ctest --output-on-failure --timeout 600 -j "$(nproc)" "$@"
