#!/usr/bin/env bash
# emu/bootstrap.sh's standard output is the toolchain prefix and nothing else: callers capture it
# (ci/common.sh: toolchain=$(emu/bootstrap.sh)). Stand-ins for dpkg-query and apt-get on PATH
# report packages missing and print apt's chatter on stdout, as the real ones do.
#   case 1: apt-get "installs" the packages, and a cached toolchain that did not run for want of
#           them now runs: stdout must be exactly the prefix.
#   case 2: apt-get installs nothing: the bootstrap stops, and stdout must be empty.
set -uo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

mkdir -p "$tmp/bin"
# dpkg-query: nothing is installed until $tmp/installed exists.
cat > "$tmp/bin/dpkg-query" <<'STUB'
#!/bin/sh
[ -e "$STUB_DIR/installed" ] || exit 1
pkg=$(eval echo "\${$#}")
ver=$(grep -h "^$pkg=" "$STUB_LOCK" | cut -d= -f2)
printf 'install ok installed %s\n' "${ver:-1.0}"
STUB
# apt-get: chatters on stdout; installs only when STUB_INSTALLS=1.
cat > "$tmp/bin/apt-get" <<'STUB'
#!/bin/sh
echo "Reading package lists... Done"
echo "Get:1 http://deb.example bookworm InRelease [151 kB]"
echo "Setting up $*"
[ "$STUB_INSTALLS" = 1 ] && touch "$STUB_DIR/installed"
exit 0
STUB
chmod +x "$tmp/bin/dpkg-query" "$tmp/bin/apt-get"
export STUB_DIR=$tmp STUB_LOCK=$root/emu/toolchain.lock
export BFIN_TOOLCHAIN_CACHE=$tmp/cache
export PATH="$tmp/bin:$PATH"

prefix=$("$root/emu/bootstrap.sh" --print-prefix) || fail "--print-prefix failed"
# A cached toolchain whose tools run only once the host packages are there.
mkdir -p "$prefix/bin"
touch "$prefix/.complete"
for t in bfin-elf-gcc bfin-elf-run; do
  cat > "$prefix/bin/$t" <<STUB
#!/bin/sh
[ -e "$tmp/installed" ] || exit 127
case "\$1" in -print-prog-name=*) echo "$prefix/bin/cc1" ;; esac
exit 0
STUB
  chmod +x "$prefix/bin/$t"
done
cp "$prefix/bin/bfin-elf-gcc" "$prefix/bin/cc1"

# Case 1
out=$(STUB_INSTALLS=1 "$root/emu/bootstrap.sh" 2>"$tmp/err1"); rc=$?
[ $rc -eq 0 ] || { cat "$tmp/err1"; fail "case 1: bootstrap exited $rc"; }
[ "$out" = "$prefix" ] || fail "case 1: stdout is not the prefix alone: '$out'"
grep -q "Reading package lists" "$tmp/err1" || fail "case 1: apt-get's output should reach stderr"

# Case 2
rm -f "$tmp/installed"
out=$(STUB_INSTALLS=0 "$root/emu/bootstrap.sh" 2>"$tmp/err2"); rc=$?
[ $rc -ne 0 ] || fail "case 2: bootstrap should fail when the packages stay missing"
[ -z "$out" ] || fail "case 2: stdout should be empty, got '$out'"
grep -q "still missing" "$tmp/err2" || { cat "$tmp/err2"; fail "case 2: no 'still missing' error"; }
echo "PASS: bootstrap stdout is the prefix alone (case 1), empty on failure (case 2)"
