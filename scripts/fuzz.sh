#!/usr/bin/env bash
# Builds Plume's libFuzzer targets with clang-14 (ASan + UBSan + coverage) in
# ${PLUME_FUZZ_BUILD_DIR:-build-fuzz} and runs each for SECONDS (default 30)
# on its committed seed corpus: the "fuzz" ctest label. Not part of
# scripts/test.sh (a separate compiler configuration); see Documentation/Testing.md.
#   bash scripts/fuzz.sh [SECONDS]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PLUME_FUZZ_BUILD_DIR:-$root/build-fuzz}"
seconds="${1:-30}"
bash "$root/scripts/install-deps.sh"
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 -DPLUME_FUZZ=ON \
  -DPLUME_WRAP_PYTHON=OFF -DPLUME_FUZZ_SECONDS="$seconds" \
  -DPython3_EXECUTABLE=/usr/bin/python3 "${launcher[@]}" "${@:2}"
cmake --build "$build" --parallel "$(nproc)" --target plumeFuzzScene plumeFuzzDatasetReader plumeFuzzParameterTable
cd "$build"
ctest -L fuzz --output-on-failure
