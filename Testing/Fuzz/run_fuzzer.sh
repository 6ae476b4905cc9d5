#!/usr/bin/env bash
# run_fuzzer.sh MODE FUZZER SEEDS WORK [N]: runs a libFuzzer target on a copy
# of its committed seeds (plus, for the reader, seeds made from the shared
# data's first 16 KB) in WORK/corpus and fails on a crash, a sanitizer report
# (leaks included), a timeout or an out-of-memory stop. MODE:
#   replay   every seed and regression input once, in one process (-runs=0);
#   explore  N mutated inputs from libFuzzer seed PLUME_FUZZ_SEED (default 1),
#            in one process (-runs=N, no fork mode): the same commit runs
#            exactly the same inputs whatever the machine's load;
#   fork     N seconds in fork mode with a new seed (PLUME_FUZZ_SEED, default 0
#            = random) that keeps going past out-of-memory inputs;
#            scripts/fuzz.sh, never CI (its outcome depends on time and load).
# On a finding it prints the sanitizer's or libFuzzer's report with its stack
# and each artifact in base64 (with the seed file it came from, if any).
set -euo pipefail
mode="$1" fuzzer="$2" seeds="$3" work="$4" n="${5:-}"
rm -rf "$work/corpus" "$work/findings" && mkdir -p "$work/corpus" "$work/findings"
cp "$seeds"/* "$work/corpus/"
if [[ "$(basename "$fuzzer")" == plumeFuzzDatasetReader && -d "${PLUME_DATA_DIR:-}" ]]; then
  # format byte (see plumeFuzzDatasetReader.cxx) + the head of each shared file
  declare -A code=([vtk]=0 [vtp]=1 [vtu]=2 [vti]=3 [ex2]=4 [geo]=5 [pvd]=6 [bin]=7)
  while IFS= read -r f; do
    ext="${f##*.}"
    [[ -n "${code[$ext]:-}" ]] || continue
    { printf "\\$(printf '%03o' "${code[$ext]}")"; head -c 16384 "$f"; } > "$work/corpus/shared_$(basename "$f")"
  done < <(find "$PLUME_DATA_DIR" -type f | sort)
fi
# A header-announced huge allocation (VTK's readers allocate what a header
# promises) is not a finding: ASan's malloc returns NULL above 2 GB, which VTK
# reports as an allocation error and Plume as one clear error. libFuzzer's own
# malloc limit is set above it so it never sees such a request (its
# out-of-memory stop would end the run). A huge operator new still ends the
# process under ASan (its new reports instead of throwing std::bad_alloc):
# that is a finding.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}allocator_may_return_null=1:max_allocation_size_mb=2048"
limits=(-rss_limit_mb=6144 -malloc_limit_mb=4096 -timeout=60)
# Address randomization off: libFuzzer keys its tables of recent comparisons
# (which feed its mutations) by code address, so with ASLR the same seed
# explores different inputs in each run.
# And a fixed environment (the sanitizers' variables, PLUME_DATA_DIR,
# PLUME_READER_ISOLATION, PATH
# and HOME): the stack starts below the environment, and libFuzzer's
# comparison dictionary picks up stack addresses, so a CI job's changing
# variables would change the exploration too.
norandom=(env -i PATH="$PATH" HOME="${HOME:-/}")
while IFS= read -r var; do
  norandom+=("$var")
done < <(env | grep -E '^(PLUME_DATA_DIR=|PLUME_READER_ISOLATION=|ASAN_OPTIONS=|LSAN_OPTIONS=|UBSAN_OPTIONS=|LD_PRELOAD=)' | sort)
if setarch "$(uname -m)" -R true 2>/dev/null; then
  norandom+=(setarch "$(uname -m)" -R)
elif [[ "$mode" == explore ]]; then
  echo "warning: setarch -R failed; this exploration's inputs may differ from another run's"
fi
log="$work/fuzz.log"
cd "$work/findings"
status=0
case "$mode" in
  replay)
    echo "replaying $(ls "$work/corpus" | wc -l) inputs of $seeds${PLUME_DATA_DIR:+ (reader: + shared data heads)}"
    "${norandom[@]}" "$fuzzer" "$work/corpus" -seed=1 -runs=0 "${limits[@]}" -artifact_prefix="$work/findings/" \
      -print_final_stats=1 >"$log" 2>&1 || status=$?
    grep -E '^#[0-9]+[[:space:]]+(INITED|DONE)|^stat::number_of_executed_units' "$log" || true ;;
  explore)
    # -reload=0: new inputs come only from this process's own mutations
    "${norandom[@]}" "$fuzzer" "$work/corpus" -seed="${PLUME_FUZZ_SEED:-1}" -runs="$n" -max_len=65536 -reload=0 \
      "${limits[@]}" -artifact_prefix="$work/findings/" -print_final_stats=1 >"$log" 2>&1 || status=$?
    grep -E '^INFO: Seed:|^#[0-9]+[[:space:]]+(INITED|DONE)|^stat::' "$log" || true ;;
  fork)
    # Fork mode keeps fuzzing past out-of-memory inputs (-ignore_ooms); crashes and timeouts stop it.
    "$fuzzer" "$work/corpus" -fork=1 -ignore_ooms=1 -ignore_timeouts=0 -ignore_crashes=0 \
      -seed="${PLUME_FUZZ_SEED:-0}" -max_total_time="$n" -max_len=65536 "${limits[@]}" \
      -artifact_prefix="$work/findings/" -print_final_stats=1 >"$log" 2>&1 || status=$?
    tail -25 "$log"
    if ls "$work/findings"/oom-* >/dev/null 2>&1; then
      echo "out-of-memory inputs (not failures in fork mode): $(ls "$work/findings"/oom-* | wc -l)"
    fi ;;
  *) echo "run_fuzzer.sh: unknown mode '$mode' (replay, explore or fork)" >&2; exit 2 ;;
esac
shopt -s nullglob
findings=("$work/findings"/crash-* "$work/findings"/leak-* "$work/findings"/timeout-*)
if [[ "$mode" != fork ]]; then
  findings+=("$work/findings"/oom-*)
fi
if [[ $status -ne 0 || ${#findings[@]} -gt 0 ]]; then
  echo "FAILED (exit $status), full log: $log"
  # the report: from the first sanitizer or libFuzzer error line to the summary
  awk '/^==[0-9]+==ERROR|^==[0-9]+== ERROR|runtime error:|^ALARM:|^reader output fails/ {on=1}
       on {print; if (++k > 150) exit} /^SUMMARY:/ && on {exit}' "$log"
  for f in "${findings[@]}"; do
    sha="$(sha1sum <"$f" | cut -d' ' -f1)"
    from=""
    for s in "$work/corpus"/*; do
      [[ "$(sha1sum <"$s" | cut -d' ' -f1)" == "$sha" ]] && from=" (= seed $(basename "$s"))" && break
    done
    echo "artifact $(basename "$f")$from, $(stat -c %s "$f") bytes, base64:"
    base64 -w 76 "$f"
  done
  exit 1
fi
