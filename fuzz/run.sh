#!/usr/bin/env bash
# One fuzz test (fuzz/driver.cmake): gathers a target's seeds, runs its libFuzzer binary for a
# time (--seconds; the environment's BVB_FUZZ_SECONDS wins) or a number of inputs (--runs), and
# fails on any finding. Prints libFuzzer's final statistics and the corpus size.
#   exit 0: no finding; 1: a finding (the input is saved in the work directory) or libFuzzer
#   failed; 77: skipped (no clang; --skip says why).
set -uo pipefail
target='' fuzzer='' source='' frames_real='' work='' max_len=4096 dict=() seconds='' runs='' seeds=()
while [ $# -gt 0 ]; do
  case $1 in
    --target) target=$2 ;;
    --fuzzer) fuzzer=$2 ;;
    --source) source=$2 ;;
    --frames-real) frames_real=$2 ;;
    --work) work=$2 ;;
    --max-len) max_len=$2 ;;
    --seconds) seconds=$2 ;;
    --runs) runs=$2 ;;
    --dict) dict=(-dict="$2") ;;
    --seeds) seeds+=("$2") ;;
    --skip) echo "fuzz tests skipped: $2"; exit 77 ;;
    *) echo "run.sh: unknown argument $1" >&2; exit 2 ;;
  esac
  shift 2
done
[ -x "$fuzzer" ] || { echo "run.sh: $fuzzer: no fuzz target (was the fuzzers sub-build built?)" >&2; exit 1; }

# Seeds: each glob is under the source tree; ../shared/frames-real/ stands for the real frames
# wherever they are (absent: those seeds are left out, as the other tests skip them).
mkdir -p "$work/corpus"
rm -rf "$work/seeds"
mkdir -p "$work/seeds"
shopt -s nullglob
n=0
for g in "${seeds[@]}"; do
  case $g in
    ../shared/frames-real/*) pattern="$frames_real/${g#../shared/frames-real/}" ;;
    *) pattern="$source/$g" ;;
  esac
  for f in $pattern; do
    [ -f "$f" ] || continue
    n=$((n + 1))
    cp "$f" "$work/seeds/$n-$(basename "$f")"
  done
done
[ "$n" -gt 0 ] || { echo "run.sh: $target: no seeds found (${seeds[*]})" >&2; exit 1; }
echo "fuzz_$target: $n seed files, $(ls "$work/corpus" | wc -l) inputs kept from earlier runs"

limit=()
if [ -n "$runs" ]; then limit=(-runs="$runs")
else limit=(-max_total_time="${BVB_FUZZ_SECONDS:-${seconds:-60}}")
fi
# -timeout: an input taking 10 s is a hang. -rss_limit_mb / -malloc_limit_mb: the largest legal
# input (a 4096x4096 RGB frame, a 128 MB .flo) fits well below 2 GB. New inputs go to corpus/,
# findings to $work/crash-* (or leak-, timeout-, oom-).
log="$work/fuzz.log"
"$fuzzer" "${limit[@]}" "${dict[@]}" -max_len="$max_len" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048 \
  -print_final_stats=1 -artifact_prefix="$work/" "$work/corpus" "$work/seeds" >"$log" 2>&1
rc=$?
# ASan's leak check is on; the final statistics and any report are what a reader needs.
if [ "$rc" -ne 0 ]; then
  echo "fuzz_$target: FINDING (libFuzzer exit $rc); the input is saved as:"
  ls "$work"/crash-* "$work"/leak-* "$work"/timeout-* "$work"/oom-* 2>/dev/null
  echo "replay: $fuzzer <that file>; the last of the log ($log):"
  tail -n 60 "$log"
  exit 1
fi
grep -E '^(Done|stat::number_of_executed_units|stat::average_exec_per_sec|stat::new_units_added|stat::peak_rss_mb)' "$log"
echo "fuzz_$target: no finding; corpus $(ls "$work/corpus" | wc -l) inputs, $(du -sk "$work/corpus" | cut -f1) KB"
