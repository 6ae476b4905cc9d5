#!/usr/bin/env bash
# Set-up command 2: install what is missing, build, and run the whole test
# suite headless (a private Xvfb for VTK's X-only render windows), then the
# ParaView plugin's tests (scripts/test-paraview.sh: built and run inside a
# private Debian root, because ParaView's packages conflict with the VTK 9.1
# build's). PLUME_SKIP_PARAVIEW=1 skips the plugin.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PLUME_BUILD_DIR:-$root/build}"
bash "$root/scripts/build.sh"
status=0
(cd "$build" && xvfb-run -a -s "-screen 0 1024x768x24 -noreset" \
  ctest --output-on-failure --timeout 600 -j "$(nproc)" "$@") || status=$?
if [ "${PLUME_SKIP_PARAVIEW:-0}" != 1 ]; then
  bash "$root/scripts/test-paraview.sh" || status=$?
fi
exit $status
