#!/usr/bin/env bash
# The sanitizer run (ctest label "sanitize" of the main build; scripts/test.sh
# runs it after the main suite and the ParaView plugin's tests; PLUME_SANITIZE=0
# skips it): one clang-14 build with AddressSanitizer + UndefinedBehaviorSanitizer
# (+ LeakSanitizer) and libFuzzer coverage (-DPLUME_FUZZ=ON) in
# ${PLUME_SANITIZE_BUILD_DIR:-build-sanitize} of what the run needs: the
# libraries, the command line, the tests that exercise Plume's CPU code and the
# fuzz targets (no Python wrappers, no benchmarks, no long GL image tests:
# -DPLUME_BUILD_BENCHMARKS=OFF -DPLUME_GL_IMAGE_TESTS=OFF); then those tests
# (any sanitizer report aborts its test), then the fuzz label: for each fuzz
# target a replay of every committed seed and regression input, and a bounded
# exploration of a fixed number of inputs from a fixed libFuzzer seed
# (PLUME_FUZZ_SEED, default 1), each in one process without fork mode, so that
# the same commit runs exactly the same inputs whatever the machine's load and
# a finding reproduces (Testing/Fuzz/CMakeLists.txt). Open-ended fuzzing with
# new seeds (fork mode, a time limit) is scripts/fuzz.sh, never CI.
# Prints the time of each stage. See Documentation/Testing.md.
#   bash scripts/test-sanitize.sh [extra ctest arguments]
#   PLUME_SANITIZE_BUILD_ONLY=1: configure and build, run nothing (scripts/test.sh
#   builds this way in the background while the main suite runs).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PLUME_SANITIZE_BUILD_DIR:-$root/build-sanitize}"
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
data=()
if [ -n "${PLUME_DATA_DIR:-}" ]; then
  data=(-DPLUME_DATA_DIR="$PLUME_DATA_DIR")
fi
t0=$SECONDS
# -O1 -g1: fast enough to run the suite, line numbers in reports; each
# library's sources compiled as one (PLUME_UNITY_BUILD_LIBRARIES: a fifth less CPU)
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DCMAKE_C_FLAGS_RELEASE="-O1 -DNDEBUG" \
  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 -DPLUME_FUZZ=ON -DPLUME_UNITY_BUILD_LIBRARIES=ON \
  -DPLUME_WRAP_PYTHON=OFF -DPLUME_BUILD_BENCHMARKS=OFF -DPLUME_GL_IMAGE_TESTS=OFF \
  -DPython3_EXECUTABLE=/usr/bin/python3 "${launcher[@]}" "${data[@]}"
cmake --build "$build" --parallel "$(nproc)"
t1=$SECONDS
if [ "${PLUME_SANITIZE_BUILD_ONLY:-0}" = 1 ]; then
  echo "sanitizer build: $((t1 - t0)) s"
  exit 0
fi
cd "$build"
# LeakSanitizer is on. Mesa's GLX driver and Open MPI's plugins (hypre's
# pressure solve) are dlopen()ed and unloaded at exit, which left what they
# still held as leaks from "<unknown module>"; the preloaded shim keeps every
# module mapped (its dlclose does nothing) so that the suppressions file can
# name those libraries. It names no Plume code.
shim="$build/lib/libplumeKeepModulesLoaded.so"
export LD_PRELOAD="$shim${LD_PRELOAD:+:$LD_PRELOAD}"
export LSAN_OPTIONS="suppressions=$root/Testing/Sanitize/lsan.supp:print_suppressions=0:${LSAN_OPTIONS:-}"
# intercept_tls_get_addr=0: clang 14's LeakSanitizer misreads glibc 2.36's
# dynamic-TLS blocks (those of dlopen()ed modules: Mesa) and its tracer then
# dies with SIGSEGV at exit ("Tracer caught signal 11", "DTLS 13 at 0xfd4"),
# aborting a test that passed: 1 run in 3 of TestSheetUpload here, and
# TestVolumePreIntegration in CI. google/sanitizers#1322 gives this workaround;
# only the dynamic TLS of such modules is no longer scanned for pointers.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=0:intercept_tls_get_addr=0:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:${UBSAN_OPTIONS:-}"
status=0
# soak: its 150 frames x 3 under ASan take minutes and add no code path the
# other tests miss; compat: compiles against ParaView's headers, no run;
# TestSmokeSolverPressure: its 128^3 iteration-growth solves take 90 s under
# ASan, and the same pressure-solve code runs in the other solver tests.
xvfb-run -a -s "-screen 0 1024x768x24 -noreset" \
  ctest --output-on-failure --timeout 900 -j "$(nproc)" -LE "soak|compat|fuzz" \
  -E "TestSmokeSolverPressure" "$@" || status=$?
t2=$SECONDS
unset LD_PRELOAD
ctest --output-on-failure -j "$(nproc)" -L fuzz || status=$?
t3=$SECONDS
echo "sanitizer run: build $((t1 - t0)) s, tests $((t2 - t1)) s, fuzz $((t3 - t2)) s"
exit $status
