#!/usr/bin/env bash
# Open-ended fuzzing (never CI): builds Plume's libFuzzer targets with clang-14
# (ASan + UBSan + coverage) in ${PLUME_FUZZ_BUILD_DIR:-build-fuzz} and runs
# each for SECONDS (default 300) in libFuzzer's fork mode with a new random
# seed (PLUME_FUZZ_SEED to repeat one), on its committed seed corpus (and, for
# the reader, the shared data's heads); findings stay in
# build-fuzz/Testing/Fuzz/<target>/fork/findings/. CI's deterministic fuzz
# tests (replay + a fixed number of runs from a fixed seed) are the ctest
# label "fuzz" of the sanitizer run (scripts/test-sanitize.sh). See
# Documentation/Testing.md.
#   bash scripts/fuzz.sh [SECONDS [TARGET...]]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PLUME_FUZZ_BUILD_DIR:-$root/build-fuzz}"
seconds="${1:-300}"
targets=("${@:2}")
if [ ${#targets[@]} -eq 0 ]; then
  targets=(plumeFuzzScene plumeFuzzDatasetReader plumeFuzzParameterTable)
fi
bash "$root/scripts/install-deps.sh"
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 -DPLUME_FUZZ=ON \
  -DPLUME_WRAP_PYTHON=OFF -DPython3_EXECUTABLE=/usr/bin/python3 "${launcher[@]}"
cmake --build "$build" --parallel "$(nproc)" --target "${targets[@]}" plumeKeepModulesLoaded
declare -A corpus=([plumeFuzzScene]=scene [plumeFuzzDatasetReader]=reader [plumeFuzzParameterTable]=params)
data_dir="$(sed -n 's/^PLUME_DATA_DIR:PATH=//p' "$build/CMakeCache.txt")"
status=0
for t in "${targets[@]}"; do
  echo "== $t: $seconds s, fork mode"
  env PLUME_DATA_DIR="${PLUME_DATA_DIR:-$data_dir}" LD_PRELOAD="$build/lib/libplumeKeepModulesLoaded.so" \
    ASAN_OPTIONS="detect_leaks=1" UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
    LSAN_OPTIONS="suppressions=$root/Testing/Sanitize/lsan.supp:print_suppressions=0" \
    bash "$root/Testing/Fuzz/run_fuzzer.sh" fork "$build/bin/$t" "$root/Testing/Fuzz/corpus/${corpus[$t]}" \
    "$build/Testing/Fuzz/$t/fork" "$seconds" || status=1
done
exit $status
