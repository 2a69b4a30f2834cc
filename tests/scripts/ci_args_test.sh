#!/usr/bin/env bash
# ci/test.sh passes its arguments to ctest and ci/main.sh to bfbench bench, as the README says
# (ci/test.sh -R cli, ci/main.sh -k sobel3x3_u8). The scripts run from a copy of ci/ beside a
# stand-in emu/bootstrap.sh, with stand-ins for dpkg-query, cmake, ctest and bfbench that record
# how they were called: nothing is installed, built or run.
set -uo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

mkdir -p "$tmp/repo/ci" "$tmp/repo/emu" "$tmp/bin" "$tmp/build/harness"
cp "$root"/ci/*.sh "$tmp/repo/ci/"
printf '#!/bin/sh\necho /opt/stand-in-toolchain\n' > "$tmp/repo/emu/bootstrap.sh"
# Every host package is installed; cmake configures and builds nothing.
printf '#!/bin/sh\necho "install ok installed"\n' > "$tmp/bin/dpkg-query"
printf '#!/bin/sh\nexit 0\n' > "$tmp/bin/cmake"
for tool in "$tmp/bin/ctest" "$tmp/build/harness/bfbench"; do
  printf '#!/bin/sh\nprintf "%%s\\n" "$(basename "$0") $*" >> "$CALLS"\n' > "$tool"
done
chmod +x "$tmp/repo/emu/bootstrap.sh" "$tmp"/bin/* "$tmp/build/harness/bfbench"
export PATH="$tmp/bin:$PATH" BVB_BUILD_DIR="$tmp/build" CALLS="$tmp/calls"

"$tmp/repo/ci/test.sh" -R 'robust|Formats' -L cli >/dev/null 2>&1 || fail "ci/test.sh failed"
grep -qx -- "ctest --output-on-failure -j $(nproc) -R robust|Formats -L cli" "$tmp/calls" ||
  fail "ci/test.sh did not pass its arguments to ctest: $(cat "$tmp/calls")"
: > "$tmp/calls"
"$tmp/repo/ci/main.sh" -k sobel3x3_u8 --size 160x120 >/dev/null 2>&1 || fail "ci/main.sh failed"
grep -qx -- "bfbench bench -k sobel3x3_u8 --size 160x120" "$tmp/calls" ||
  fail "ci/main.sh did not pass its arguments to bfbench bench: $(cat "$tmp/calls")"
echo "ok: ci/test.sh -> ctest, ci/main.sh -> bfbench bench, arguments passed on"
