#!/usr/bin/env bash
# Set-up command 2: install what is missing, build, and run every test
# headless (a private Xvfb for VTK's X-only render windows), in three parts:
#  1. the suite of the VTK 9.1 build, all but the label "sanitize";
#  2. the ParaView plugin's tests (scripts/test-paraview.sh: built and run
#     inside a private Debian root, because ParaView's packages conflict with
#     the VTK 9.1 build's); PLUME_SKIP_PARAVIEW=1 skips them;
#  3. the label "sanitize" alone: the libraries, the command line, the tests
#     of Plume's CPU code and the fuzz targets in a clang ASan + UBSan + LSan
#     build, those tests, then each fuzzer's deterministic replay and
#     fixed-seed, fixed-count exploration (scripts/test-sanitize.sh);
#     PLUME_SANITIZE=0 skips it.
# Arguments go to the first ctest instead (e.g. -R Volume), and then only
# part 1 runs. See Documentation/Testing.md.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PLUME_BUILD_DIR:-$root/build}"
sanitize=ON
if [ "${PLUME_SANITIZE:-1}" = 0 ]; then sanitize=OFF; fi
bash "$root/scripts/build.sh" -DPLUME_SANITIZE_SUITE=$sanitize
status=0
if [ $# -gt 0 ]; then
  (cd "$build" && xvfb-run -a -s "-screen 0 1024x768x24 -noreset" \
    ctest --output-on-failure --timeout 600 -j "$(nproc)" "$@") || status=$?
  exit $status
fi
(cd "$build" && xvfb-run -a -s "-screen 0 1024x768x24 -noreset" \
  ctest --output-on-failure --timeout 600 -j "$(nproc)" -LE sanitize) || status=$?
if [ "${PLUME_SKIP_PARAVIEW:-0}" != 1 ]; then
  bash "$root/scripts/test-paraview.sh" || status=$?
fi
if [ "$sanitize" = ON ]; then
  (cd "$build" && ctest --output-on-failure -L sanitize) || status=$?
fi
exit $status
