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
if [ $# -eq 0 ] && [ "$sanitize" = ON ]; then
  # Part 3's build (clang, ASan) runs at low priority beside parts 1 and 2:
  # their GL tests and pvbatch start-ups leave a core idle much of the time.
  # Same build dir and data dir as the ctest test Plume.Sanitize.Suite, whose
  # own build step then finds nothing to do.
  # (CMake makes the data dir absolute without resolving links: realpath -s)
  data_dir="$(realpath -m -s "$(sed -n 's/^PLUME_DATA_DIR:[A-Z]*=//p' "$build/CMakeCache.txt")")"
  PLUME_SANITIZE_BUILD_ONLY=1 PLUME_SANITIZE_BUILD_DIR="$(cd "$build" && pwd)/sanitize" PLUME_DATA_DIR="$data_dir" \
    nice -n 10 bash "$root/scripts/test-sanitize.sh" >"$build/sanitize-build.log" 2>&1 &
  sanitize_build=$!
fi
if [ $# -gt 0 ]; then
  (cd "$build" && xvfb-run -a -s "-screen 0 1024x768x24 -noreset" \
    ctest --output-on-failure --timeout 600 -j "$(nproc)" "$@") || status=$?
  exit $status
fi
# The plugin's build below compiles most modules against ParaView's VTK 9.2,
# so the compile check Plume.Compat.ParaViewVTK92 checks only the rest.
compat_env=()
if [ "${PLUME_SKIP_PARAVIEW:-0}" != 1 ]; then compat_env=(PLUME_COMPAT_PLUGIN_BUILDS=1); fi
(cd "$build" && env "${compat_env[@]}" xvfb-run -a -s "-screen 0 1024x768x24 -noreset" \
  ctest --output-on-failure --timeout 600 -j "$(nproc)" -LE sanitize) || status=$?
if [ "${PLUME_SKIP_PARAVIEW:-0}" != 1 ]; then
  bash "$root/scripts/test-paraview.sh" || status=$?
fi
if [ "$sanitize" = ON ]; then
  # A failed background build is reported here; the ctest run builds again
  # and shows the compiler's errors.
  wait "$sanitize_build" || { echo "test.sh: the background sanitizer build failed:"; tail -n 40 "$build/sanitize-build.log"; }
  (cd "$build" && ctest --output-on-failure -L sanitize) || status=$?
fi
exit $status
