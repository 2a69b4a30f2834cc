#!/usr/bin/env bash
# --timing-profile FILE --timing-profile-window START,END: runs profile_hazards.s and checks
# that each labelled hazard is charged to exactly its instruction, with the cause and cycles
# the rules give (see the program's comments); that no other instruction of the window has
# any stall; that each record's cycles are its count plus its causes; that the window's
# total is the sum of its records; and that nothing outside the window is recorded.
#   emu/tests/timing/profile.sh PREFIX [SIM-OPTIONS...]   (PREFIX as sim_testsuite.sh's)
set -uo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
prefix=${1:?usage: profile.sh PREFIX [SIM-OPTIONS...]}; shift
suite=$prefix/share/bfin-sim-testsuite
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0
ok() { echo "PASS: $*"; }
bad() { echo "FAIL: $*"; fails=$((fails + 1)); }

"$prefix/bin/bfin-elf-as" -I "$suite" "$here/profile_hazards.s" -o "$tmp/p.o" &&
  "$prefix/bin/bfin-elf-ld" -Ttext=0xffa00000 -Tdata=0xff806800 "$tmp/p.o" -o "$tmp/p.x" ||
  { echo "FAIL: profile_hazards.s did not build"; exit 1; }
addr() { "$prefix/bin/bfin-elf-nm" "$tmp/p.x" | awk -v s="$1" '$3 == s { print $1 }'; }
start=$(addr h_start) end=$(addr h_end)
# The program's own checks run under the test suite's runner (ctest sim_timing); here only the
# profile it leaves is judged.
"$prefix/bin/bfin-elf-run" --environment operating --timing bf537 "$@" \
  --timing-profile "$tmp/p.prof" --timing-profile-window "0x$start,0x$end" "$tmp/p.x" >/dev/null 2>&1
[[ -s $tmp/p.prof ]] || { echo "FAIL: no profile written"; exit 1; }

# cause NAME -> its column (records: pc count cycles causes... reg)
col() { awk -v c="$1" '$1 == "causes" { for (i = 2; i <= NF; i++) if ($i == c) print i + 2 }' "$tmp/p.prof"; }
field() { # LABEL COLUMN
  awk -v pc="$(addr "$1")" -v c="$2" '$1 == pc { print $c }' "$tmp/p.prof"
}
expect() { # LABEL CAUSE VALUE (VALUE "+" means > 0)
  local got; got=$(field "$1" "$(col "$2")")
  if [[ $3 == + ]]; then [[ -n $got && $got -gt 0 ]] && ok "$1 $2 = $got" || bad "$1 $2 = '$got', expected > 0"
  else [[ $got == "$3" ]] && ok "$1 $2 = $3" || bad "$1 $2 = '$got', expected $3"; fi
}
expect h_load_use areg_load 3
expect h_move_use areg_move 4
expect h_coll l1_collision 1
expect h_jump multicycle 4
expect h_mmr mmr +
reg() { awk -v pc="$(addr "$1")" '$1 == pc { print $NF }' "$tmp/p.prof"; }
[[ $(reg h_load_use) == P0 ]] && ok "h_load_use waited for P0" || bad "h_load_use stall register '$(reg h_load_use)'"
[[ $(reg h_move_use) == P2 ]] && ok "h_move_use waited for P2" || bad "h_move_use stall register '$(reg h_move_use)'"
[[ $(field h_loop 2) == 10 ]] && ok "h_loop ran 10 times" || bad "h_loop count '$(field h_loop 2)'"

# Exactly those five instructions have any cause; every record adds up; nothing outside.
hazards=" $(addr h_load_use) $(addr h_move_use) $(addr h_coll) $(addr h_jump) $(addr h_mmr) "
while read -r pc count cycles rest; do
  read -ra c <<<"$rest"; sum=0
  for ((i = 0; i < ${#c[@]} - 1; i++)); do sum=$((sum + c[i])); done
  [[ $cycles == $((count + sum)) ]] || bad "record $pc: cycles $cycles != count $count + causes $sum"
  if [[ $hazards != *" $pc "* ]]; then
    ((sum == 0)) || bad "record $pc has causes ($rest) but no hazard"
  fi
  [[ $((16#$pc)) -ge $((16#$start)) && $((16#$pc)) -lt $((16#$end)) ]] || bad "record $pc outside the window"
done < <(awk '$1 ~ /^[0-9a-f]{8}$/' "$tmp/p.prof")
total=$(awk '$1 ~ /^[0-9a-f]{8}$/ { s += $3 } END { print s }' "$tmp/p.prof")
win=$(awk '$1 == "window" && $2 == "0" { print $4 }' "$tmp/p.prof")
[[ $win == "$total" ]] && ok "window total $win = sum of records" || bad "window total '$win' != records' $total"
((fails == 0)) && echo "profile: all passed" || echo "profile: $fails failed"
((fails == 0))
