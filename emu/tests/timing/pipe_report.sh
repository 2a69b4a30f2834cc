#!/usr/bin/env bash
# --timing-report FILE: the totals written at exit.  Runs pipe_areg_load.s and
# pipe_pushpop.s with the report on and checks the causes against the counts worked out in
# those tests' comments:
#   pipe_areg_load.s: address-register load stalls 3 + 1 + 0 + 0 + 3 + 0 + 3 = 10
#   pipe_pushpop.s:   push/pop multiple (6-14) + (5-11) + (1-14) + (1-11) + 0 + 0 = -37,
#                     one load stall of 3 (block 4)
# and that total_cycles = base_cycles + every cause.
#   emu/tests/timing/pipe_report.sh PREFIX [SIM-OPTIONS...]   (PREFIX as sim_testsuite.sh's)
set -uo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
prefix=${1:?usage: pipe_report.sh PREFIX [SIM-OPTIONS...]}; shift
suite=$prefix/share/bfin-sim-testsuite
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0
check() { # test key expected
  local got
  got=$(awk -v k="$2" '$1 == k { print $2 }' "$tmp/$1.rep")
  if [[ $got == "$3" ]]; then echo "PASS: $1 $2 = $3"
  else echo "FAIL: $1 $2 = '$got', expected $3"; fails=$((fails + 1)); fi
}
for t in pipe_areg_load pipe_pushpop; do
  "$prefix/bin/bfin-elf-as" -I "$suite" "$here/$t.s" -o "$tmp/$t.o" &&
    "$prefix/bin/bfin-elf-ld" -Ttext=0xffa00000 -Tdata=0xff800000 "$tmp/$t.o" -o "$tmp/$t.x" &&
    "$prefix/bin/bfin-elf-run" --environment operating --timing bf537 "$@" \
      --timing-report "$tmp/$t.rep" "$tmp/$t.x" >/dev/null ||
    { echo "FAIL: $t did not build or run"; fails=$((fails + 1)); continue; }
done
check pipe_areg_load stall_areg_load 10
check pipe_areg_load stall_areg_move 0
check pipe_areg_load pushpop_per_register 0
check pipe_pushpop pushpop_per_register -37
check pipe_pushpop stall_areg_load 3
for t in pipe_areg_load pipe_pushpop; do
  sum=$(awk '$1 == "base_cycles" || $1 ~ /^stall_/ || $1 == "pushpop_per_register" ||
             $1 == "memory_cycles" { s += $2 } END { print s }' "$tmp/$t.rep")
  check "$t" total_cycles "$sum"
done
((fails == 0)) && echo "pipe_report: all passed" || echo "pipe_report: $fails failed"
((fails == 0))
