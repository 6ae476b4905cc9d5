#!/usr/bin/env bash
# run_fuzzer.sh FUZZER SEEDS WORK SECONDS: runs a libFuzzer target for SECONDS
# on a copy of its committed seeds (plus, for the reader, seeds made from the
# shared data's first 16 KB), keeps what it finds in WORK/findings, and fails
# when it finds a crash, a sanitizer report or a timeout. PLUME_FUZZ_SEED
# (default 0: a new random seed each run) fixes libFuzzer's seed, so that a
# run explores the same inputs again (CI: scripts/test-sanitize.sh sets 1).
set -euo pipefail
fuzzer="$1" seeds="$2" work="$3" seconds="$4"
rm -rf "$work/corpus" && mkdir -p "$work/corpus" "$work/findings"
cp "$seeds"/* "$work/corpus/"
if [[ "$(basename "$fuzzer")" == plumeFuzzDatasetReader && -d "${PLUME_DATA_DIR:-}" ]]; then
  # format byte (see plumeFuzzDatasetReader.cxx) + the head of each shared file
  declare -A code=([vtk]=0 [vtp]=1 [vtu]=2 [vti]=3 [ex2]=4 [geo]=5 [pvd]=6 [bin]=7)
  while IFS= read -r f; do
    ext="${f##*.}"
    [[ -n "${code[$ext]:-}" ]] || continue
    { printf "\\$(printf '%03o' "${code[$ext]}")"; head -c 16384 "$f"; } > "$work/corpus/shared_$(basename "$f")"
  done < <(find "$PLUME_DATA_DIR" -type f)
fi
cd "$work/findings"
# Fork mode keeps fuzzing past out-of-memory inputs (-ignore_ooms): VTK's readers allocate what a
# header announces (e.g. an XML compressed-block count), which Plume reports as a clear error
# (std::bad_alloc caught by vtkPlumeDatasetReader); crashes and timeouts still stop the run.
"$fuzzer" "$work/corpus" -fork=1 -ignore_ooms=1 -ignore_timeouts=0 -ignore_crashes=0 \
  -seed="${PLUME_FUZZ_SEED:-0}" -max_total_time="$seconds" -max_len=65536 -timeout=20 -rss_limit_mb=4096 -malloc_limit_mb=2048 \
  -artifact_prefix="$work/findings/" -print_final_stats=1 2>&1 | tail -25
status=${PIPESTATUS[0]}
if ls "$work/findings"/oom-* >/dev/null 2>&1; then
  echo "out-of-memory inputs (header-announced allocations; not failures): $(ls "$work/findings"/oom-* | wc -l)"
fi
if ls "$work/findings"/crash-* "$work/findings"/leak-* "$work/findings"/timeout-* >/dev/null 2>&1; then
  echo "findings in $work/findings:"; ls "$work/findings"
  exit 1
fi
exit "$status"
