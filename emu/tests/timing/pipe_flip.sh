#!/usr/bin/env bash
# Shows that the pipe_*.s tests can fail: runs each with the timing model the other way
# round (--timing bf537 <-> --timing none, so the model off, or on where the test expects
# the simulator's own counts) and expects every one to FAIL.
#   emu/tests/timing/pipe_flip.sh PREFIX     (PREFIX as sim_testsuite.sh's)
set -uo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
prefix=${1:?usage: pipe_flip.sh PREFIX}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for t in "$here"/pipe_*.s; do
  n=${t##*/}
  sed -e 's/--timing bf537/--timing XX/; s/--timing none/--timing bf537/; s/--timing XX/--timing none/' \
    "$t" > "$tmp/flipped_$n"
done
out=$("$here/../../sim_testsuite.sh" --prefix "$prefix" -v "$tmp"/flipped_*.s 2>&1)
printf '%s\n' "$out" | grep -E '^(PASS|FAIL|UNRESOLVED)'
total=$(printf '%s\n' "$out" | grep -cE '^(PASS|FAIL|UNRESOLVED)')
failed=$(printf '%s\n' "$out" | grep -c '^FAIL')
echo "pipe_flip: $failed of $total flipped tests failed (all must)"
((total > 0 && failed == total))
