#!/usr/bin/env bash
# examples/out-of-tree, a kernel family outside this tree, built against this build directory
# (find_package(bvb), bvb_add_kernel_family) in a temporary directory, from a copy of it:
#   - its bfbench lists its kernel alone and runs the host reference on two frames;
#   - with the toolchain: `check` passes and `budgets` holds against the example's budgets.json;
#     then the copy's assembly gets one defect (the absolute value left out), is rebuilt, and
#     both must fail (exit 1), check naming the kernel's assembly as FAILED and replaying it
#     with the family's bfbench.
# usage: out_of_tree_test.sh BUILD_DIR HOST_ONLY(ON|OFF) CMAKE GENERATOR [CMAKE_ARGS...]
set -uo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$1 host_only=$2 cmake=$3 generator=$4
shift 4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

cp -r "$root/examples/out-of-tree" "$tmp/src"
"$cmake" -S "$tmp/src" -B "$tmp/build" -G "$generator" -Dbvb_DIR="$build" "$@" > "$tmp/configure.log" 2>&1 ||
  { cat "$tmp/configure.log"; fail "the example does not configure against $build"; }
"$cmake" --build "$tmp/build" -j 2 > "$tmp/build.log" 2>&1 || { cat "$tmp/build.log"; fail "the example does not build"; }
bench=$tmp/build/bfbench-absdiff

# Its registry is the family's: absdiff_u8, with C and assembly, and none of this tree's kernels.
list=$("$bench" list) || fail "bfbench-absdiff list failed"
[ "$(printf '%s\n' "$list" | awk '{print $1, $2, $3, $4}')" = "absdiff_u8 absdiff c asm" ] ||
  fail "bfbench-absdiff list shows: $list"

# The host reference on 3x1 frames: |0-255| |200-100| |7-7|.
printf 'P5\n3 1\n255\n\000\310\007' > "$tmp/a.pgm"
printf 'P5\n3 1\n255\n\377\144\007' > "$tmp/b.pgm"
"$bench" run absdiff_u8 --impl host --in "$tmp/a.pgm" --in "$tmp/b.pgm" --out "$tmp/d.pgm" > /dev/null ||
  fail "bfbench-absdiff run --impl host failed"
[ "$(tail -c 3 "$tmp/d.pgm" | od -An -tu1 | tr -s ' ')" = " 255 100 0" ] ||
  fail "run --impl host wrote $(tail -c 3 "$tmp/d.pgm" | od -An -tu1)"

if [ "$host_only" = ON ]; then
  echo "host-only build: the example's check and budgets need the toolchain, not run"
  exit 0
fi

"$bench" check --seed 1 -j 2 > "$tmp/check.log" 2>&1 || { cat "$tmp/check.log"; fail "check of the example failed"; }
grep -q "bit-exact" "$tmp/check.log" || { cat "$tmp/check.log"; fail "check did not report bit-exact calls"; }
"$bench" budgets -j 2 > "$tmp/budgets.log" 2>&1 || { cat "$tmp/budgets.log"; fail "budgets of the example failed"; }
grep -q "absdiff_u8/asm/.* ok" "$tmp/budgets.log" || { cat "$tmp/budgets.log"; fail "budgets judged no absdiff_u8 budget"; }
echo "the example passes:"
tail -n 2 "$tmp/check.log"
cat "$tmp/budgets.log"

# One defect in the copy's assembly: without the absolute value, every pixel where b > a is wrong.
asm=$tmp/src/asm/absdiff.S
grep -q '^	r0 = abs r0;$' "$asm" || fail "the defect's line is not in $asm"
sed -i 's/^	r0 = abs r0;$/	nop;/' "$asm"
"$cmake" --build "$tmp/build" -j 2 > "$tmp/rebuild.log" 2>&1 || { cat "$tmp/rebuild.log"; fail "the broken example does not build"; }
"$bench" check --seed 1 -j 2 > "$tmp/broken_check.log" 2>&1
rc=$?
[ "$rc" = 1 ] || { cat "$tmp/broken_check.log"; fail "check of the broken assembly exited $rc, not 1"; }
grep -q "FAILED absdiff_u8 (asm)" "$tmp/broken_check.log" ||
  { cat "$tmp/broken_check.log"; fail "check of the broken assembly named no failed absdiff_u8 (asm) call"; }
grep -q "replay: bfbench-absdiff check --seed 1 --case absdiff_u8:" "$tmp/broken_check.log" ||
  { cat "$tmp/broken_check.log"; fail "the failure's replay command is not the family's bfbench"; }
"$bench" budgets -j 2 > "$tmp/broken_budgets.log" 2>&1
rc=$?
[ "$rc" = 1 ] || { cat "$tmp/broken_budgets.log"; fail "budgets of the broken assembly exited $rc, not 1"; }
echo "the broken example fails, as it must:"
grep -m 1 "FAILED absdiff_u8 (asm)" "$tmp/broken_check.log"
grep -m 1 "FAILED CHECK" "$tmp/broken_budgets.log"
echo "PASS"
