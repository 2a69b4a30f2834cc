#!/usr/bin/env bash
# Builds the bfin-elf toolchain (binutils, C-only gcc with libgcc) and the GNU Blackfin simulator
# (bfin-elf-run, with our patches) from Debian's source packages, into a cache outside the clone.
#
#   emu/bootstrap.sh                 build if needed; print the toolchain prefix on stdout
#   emu/bootstrap.sh --print-prefix  print where the toolchain is (or would be); build nothing
#   emu/bootstrap.sh --print-key     print the cache key
#   emu/bootstrap.sh --with-gdb      also bfin-elf-gdb with the simulator built in (about 25
#                                    more minutes; for bfbench debug): $prefix/bin/bfin-elf-gdb
#
# Standard output carries the prefix and nothing else (callers capture it); progress, apt-get's
# output and errors go to standard error, each stage's output to its log.
#
# Cache: $BFIN_TOOLCHAIN_CACHE, default ${XDG_CACHE_HOME:-~/.cache}/bfin-vision-bench/toolchain.
# Two parts, each keyed by what went into it, so that a simulator patch rebuilds only the
# simulator (about 2 minutes) and not gcc (15 to 35):
#   gcc-<tkey>  binutils, gcc, libgcc, libgloss headers: emu/toolchain.lock's binutils, gcc and
#               newlib lines, this script's toolchain stages, emu/patches/toolchain/*.patch
#   sim-<skey>  bfin-elf-run and its test suite: the gdb-source line, this script's simulator
#               stages, emu/patches/sim/*.patch (applied in name order)
#   tc-<tkey>-<skey>  the prefix callers use: both parts joined (hard links, so it costs no space)
#   gdb-<gkey>  only with --with-gdb: bfin-elf-gdb, from the same gdb source and simulator patches
#               as the simulator (the gdb-source line, this script's gdb stages, emu/patches/sim);
#               the prefix's bin/bfin-elf-gdb is a symbolic link to it. Not part of the prefix's
#               key: the default build is the same with or without it.
# Each part is built in work-<part> and renamed into place only when complete, so a directory named
# by its key is always whole. A failed stage removes its own build directory; stages that finished
# keep their stamps, so the next run resumes at the failed stage. Two runs at once serialise on a
# lock; the second finds the first one's result.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
lockfile="$here/toolchain.lock"
cache_root=${BFIN_TOOLCHAIN_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/bfin-vision-bench/toolchain}
jobs=${BFIN_BOOTSTRAP_JOBS:-$(nproc)}
target=bfin-elf

say() { printf '[bootstrap] %s\n' "$*" >&2; }
die() { say "error: $*"; exit 1; }

# Packages needed to build, beside the pinned source packages.
build_deps=(build-essential flex bison texinfo libgmp-dev libmpfr-dev libmpc-dev xz-utils patch file)
# And for gdb (--with-gdb): its command line's terminal library.
gdb_deps=(libncurses-dev)
mapfile -t source_pkgs < <(grep -v '^\s*#' "$lockfile" | grep -v '^\s*$')

lock_lines() { grep -v '^\s*#' "$lockfile" | grep -v '^\s*$' | grep -E "$1" || true; }
patch_text() { if [ -d "$here/patches/$1" ]; then find "$here/patches/$1" -type f -name '*.patch' -print0 | sort -z | xargs -0r cat; fi; }
host_id() { uname -m; cut -d. -f1 /etc/debian_version 2>/dev/null || true; }

# ---- stages of the toolchain part (their text is part of its key) ----

src_tarball() {  # the single tarball a glob names, or a clear error
  local matches=( $1 )
  [ -f "${matches[0]}" ] || { echo "source tarball $1 not found" >&2; return 1; }
  echo "${matches[0]}"
}

apply_patches() {  # apply_patches DIR SRC: every DIR/*.patch, in name order, with -p1 in SRC
  local p
  [ -d "$1" ] || return 0
  for p in "$1"/*.patch; do
    [ -e "$p" ] || continue
    echo "applying $p"; ( cd "$2" && patch -p1 --no-backup-if-mismatch < "$p" )
  done
}

tc_unpack() {
  local src="$work/src"
  rm -rf "$src"; mkdir -p "$src"
  tar -C "$src" -xf "$(src_tarball '/usr/src/binutils/binutils-*.tar.xz')"
  tar -C "$src" -xf "$(src_tarball '/usr/src/gcc-12/gcc-*-dfsg.tar.xz')"
  # From newlib only libgloss's Blackfin headers (MMR names: <blackfin.h>, <defBF537.h>), which
  # the simulator's test suite and bare-metal code include; no C library is built.
  tar -C "$src" -xf "$(src_tarball '/usr/src/newlib/newlib-*.tar.xz')" --wildcards '*/libgloss/bfin/include/*'
  ( cd "$src" && mv binutils-* binutils && mv gcc-* gcc && mv newlib-* newlib )
  # Debian strips the GFDL manuals from gcc; its own patch lets the build go on without them.
  ( cd "$src/gcc" && patch -p2 < /usr/src/gcc-12/debian/patches/gcc-gfdl-build.diff )
  apply_patches "$here/patches/toolchain" "$src"
  ls "$src"
}

tc_binutils() {
  "$work/src/binutils/configure" --target=$target --prefix="$stage_dir" \
    --disable-nls --disable-werror --disable-gdb --disable-sim --disable-gprofng --disable-gold
  make -j"$jobs"
  make install
}

tc_gcc() {
  "$work/src/gcc/configure" --target=$target --prefix="$stage_dir" \
    --enable-languages=c --without-headers --with-newlib --disable-multilib --disable-nls \
    --disable-shared --disable-threads --disable-libssp --disable-libquadmath --disable-libgomp \
    --disable-libatomic --disable-lto --disable-decimal-float --disable-werror
  make -j"$jobs" all-gcc all-target-libgcc
  make install-gcc install-target-libgcc
}

tc_headers() {
  mkdir -p "$stage_dir/$target/include"
  cp -a "$work/src/newlib/libgloss/bfin/include/." "$stage_dir/$target/include/"
  echo '#include <blackfin.h>' | "$target-gcc" -mcpu=bf537 -E -x c - >/dev/null
}

# ---- stages of the simulator part ----

sim_unpack() {
  local src="$work/src"
  rm -rf "$src"; mkdir -p "$src"
  tar -C "$src" -xf "$(src_tarball /usr/src/gdb.tar.xz)"
  ( cd "$src" && test -d gdb )
  apply_patches "$here/patches/sim" "$src/gdb"
}

sim_build() {
  "$work/src/gdb/configure" --target=$target --prefix="$stage_dir" \
    --enable-sim --disable-gdb --disable-gdbserver --disable-binutils --disable-ld --disable-gas \
    --disable-gprof --disable-gold --disable-gprofng --disable-nls --disable-werror \
    --disable-readline --disable-libdecnumber
  make -j"$jobs" all-sim
  make install-sim
  # The simulator's own test suite verifies this build (emu/sim_testsuite.sh); keep it with it.
  mkdir -p "$stage_dir/share/bfin-sim-testsuite"
  cp -a "$work/src/gdb/sim/testsuite/bfin/." "$stage_dir/share/bfin-sim-testsuite/"
}

# ---- stages of the gdb part (--with-gdb) ----

gdb_unpack() {
  local src="$work/src"
  rm -rf "$src"; mkdir -p "$src"
  tar -C "$src" -xf "$(src_tarball /usr/src/gdb.tar.xz)"
  ( cd "$src" && test -d gdb )
  apply_patches "$here/patches/sim" "$src/gdb"
}

gdb_build() {
  # The simulator is linked into gdb (target sim), with the same patches as bfin-elf-run.
  "$work/src/gdb/configure" --target=$target --prefix="$stage_dir" \
    --enable-sim --disable-gdbserver --disable-binutils --disable-ld --disable-gas \
    --disable-gprof --disable-gold --disable-gprofng --disable-nls --disable-werror \
    --disable-tui --without-python --without-guile --without-debuginfod --without-babeltrace \
    --without-lzma --without-xxhash --without-intel-pt
  make -j"$jobs" all-gdb
  make install-gdb
  "$stage_dir/bin/$target-gdb" -nx -batch -ex 'target sim' -ex 'show version' >/dev/null
}

tc_stages=(tc_unpack tc_binutils tc_gcc tc_headers)
sim_stages=(sim_unpack sim_build)
gdb_stages=(gdb_unpack gdb_build)

tkey=$( { lock_lines '^(binutils|gcc|newlib)'; declare -f src_tarball apply_patches "${tc_stages[@]}";
          patch_text toolchain; host_id; } | sha256sum | cut -c1-16)
skey=$( { lock_lines '^gdb'; declare -f src_tarball apply_patches "${sim_stages[@]}";
          patch_text sim; host_id; } | sha256sum | cut -c1-16)
gkey=$( { lock_lines '^gdb'; declare -f src_tarball apply_patches "${gdb_stages[@]}";
          patch_text sim; host_id; } | sha256sum | cut -c1-16)
key="$tkey-$skey"
prefix="$cache_root/tc-$key"

with_gdb=false
case "${1:-}" in
  --print-prefix) echo "$prefix"; exit 0 ;;
  --print-key) echo "$key"; exit 0 ;;
  --with-gdb) with_gdb=true; build_deps+=("${gdb_deps[@]}") ;;
  "") ;;
  -h|--help) sed -n '2,29p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
  *) die "unknown option '$1' (try --help)" ;;
esac
[ $# -le 1 ] || die "one option at most (try --help)"

# A cached toolchain must also run here: its compiler links against the host's gmp/mpfr/mpc.
toolchain_works() {
  [ -f "$1/.complete" ] &&
    "$1/bin/$target-gcc" --version >/dev/null 2>&1 &&
    "$("$1/bin/$target-gcc" -print-prog-name=cc1)" --version >/dev/null 2>&1 </dev/null &&
    "$1/bin/$target-run" --version >/dev/null 2>&1
}

installed_version() { dpkg-query -W -f='${Status} ${Version}\n' "$1" 2>/dev/null | sed -n 's/^install ok installed //p'; }

missing_packages() {
  local spec name ver
  for spec in "${source_pkgs[@]}"; do
    name=${spec%%=*}; ver=${spec#*=}
    [ "$(installed_version "$name")" = "$ver" ] || echo "$spec"
  done
  for name in "${build_deps[@]}"; do
    [ -n "$(installed_version "$name")" ] || echo "$name"
  done
}

ensure_packages() {
  local missing
  mapfile -t missing < <(missing_packages)
  [ ${#missing[@]} -eq 0 ] && return 0
  say "installing: ${missing[*]}"
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || die "need root (or sudo) to apt-get install: ${missing[*]}"
    sudo=(sudo)
  fi
  export DEBIAN_FRONTEND=noninteractive
  # apt-get talks on stdout; stdout is the prefix, so its output goes to stderr.
  "${sudo[@]}" apt-get update -q >&2 || die "apt-get update failed"
  "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}" >&2 ||
    die "apt-get install failed for: ${missing[*]}"
  mapfile -t missing < <(missing_packages)
  [ ${#missing[@]} -eq 0 ] || die "still missing after apt-get: ${missing[*]}"
}

gdb_works() { [ -f "$cache_root/gdb-$gkey/.complete" ] && [ "$1/bin/$target-gdb" -ef "$cache_root/gdb-$gkey/bin/$target-gdb" ] &&
              "$1/bin/$target-gdb" -nx -batch -ex 'show version' >/dev/null 2>&1; }
wanted_works() { toolchain_works "$1" && { ! $with_gdb || gdb_works "$1"; }; }

if wanted_works "$prefix"; then
  say "toolchain $key is cached in $prefix"
  echo "$prefix"; exit 0
fi

mkdir -p "$cache_root"
exec 9>"$cache_root/.lock"
if ! flock -n 9; then
  say "another bootstrap is building; waiting for it"
  flock 9
fi

total_t0=$(date +%s)
t0=$(date +%s)
say "stage packages: start"
ensure_packages
say "stage packages: done in $(( $(date +%s) - t0 )) s"

if wanted_works "$prefix"; then   # built by the run we waited for, or only lacked packages
  say "toolchain $key is cached in $prefix"
  echo "$prefix"; exit 0
fi

# run_stage NAME FUNCTION: skipped if stamped; otherwise runs in a fresh build/NAME directory with
# its output in logs/NAME.log; on failure prints the log's tail and removes the stage's directory.
run_stage() {
  local name=$1 fn=$2 t0 dt log="$work/logs/$1.log"
  if [ -f "$work/stamps/$name" ]; then
    say "stage $name: done by an earlier run, kept"
    return 0
  fi
  say "stage $name: start (log: $log)"
  t0=$(date +%s)
  rm -rf "${work:?}/build/$name"
  mkdir -p "$work/build/$name"
  if ! ( cd "$work/build/$name" && "$fn" ) >"$log" 2>&1 </dev/null; then
    dt=$(( $(date +%s) - t0 ))
    say "stage $name FAILED after ${dt} s; last lines of $log:"
    tail -n 25 "$log" | sed 's/^/    /' >&2
    rm -rf "${work:?}/build/$name"
    exit 1
  fi
  dt=$(( $(date +%s) - t0 ))
  touch "$work/stamps/$name"
  say "stage $name: done in ${dt} s"
}

# build_part NAME KEY STAGE...: builds one part into <cache>/NAME-KEY unless it is there.
build_part() {
  local name=$1 pkey=$2; shift 2
  local final="$cache_root/$name-$pkey"
  if [ -f "$final/.complete" ]; then say "part $name-$pkey is cached"; return 0; fi
  rm -rf "$final"
  work="$cache_root/work-$name-$pkey"
  stage_dir="$work/prefix"
  mkdir -p "$work/stamps" "$work/logs" "$work/build" "$stage_dir"
  say "building part $name-$pkey ($jobs jobs)"
  local st
  for st in "$@"; do
    ( export PATH="$stage_dir/bin:$PATH"; run_stage "$st" "$st" ) || exit 1
  done
  touch "$stage_dir/.complete"
  mv "$stage_dir" "$final"
  rm -rf "$work"
}

# gdb, on request, beside a toolchain that is there (built now, or before).
add_gdb() {
  build_part gdb "$gkey" "${gdb_stages[@]}"
  ln -sfn "$cache_root/gdb-$gkey/bin/$target-gdb" "$prefix/bin/$target-gdb"
  gdb_works "$prefix" || die "bfin-elf-gdb in $prefix does not run"
  say "bfin-elf-gdb in $prefix/bin"
}

if toolchain_works "$prefix"; then   # here only for the gdb (wanted_works said so above)
  if $with_gdb; then add_gdb; fi
  echo "$prefix"; exit 0
fi

build_part gcc "$tkey" "${tc_stages[@]}"
build_part sim "$skey" "${sim_stages[@]}"

# Join the two parts. Hard links cost no space; the parts never share a file name (binutils is
# configured without the simulator), and --remove-destination would never write through a link.
join="$cache_root/join-$key"
rm -rf "$join"
cp -al "$cache_root/gcc-$tkey" "$join"
cp -al --remove-destination "$cache_root/sim-$skey/." "$join/"
rm -f "$join/.complete"

smoke="$join/.smoke"; mkdir -p "$smoke"
cat > "$smoke/smoke.c" <<'SMOKE'
int twice(int x) { return 2 * x; }
SMOKE
cat > "$smoke/start.s" <<'SMOKE'
	.text
	.global _start
_start:
	sp.h = 0x0100; sp.l = 0x0000;
	r0 = 21;
	call _twice;
	r0 += -42;          /* exit status 0 when twice(21) == 42 */
	[--sp] = r0;
	r0 = sp;
	p0 = 1;             /* libgloss exit */
	excpt 0;
SMOKE
if ! ( cd "$smoke" && "$join/bin/$target-gcc" -O2 -c smoke.c -o smoke.o && "$join/bin/$target-as" start.s -o start.o &&
       "$join/bin/$target-ld" start.o smoke.o -o smoke.elf && "$join/bin/$target-run" smoke.elf ) >&2; then
  die "smoke test of the joined toolchain in $join failed"
fi
rm -rf "$smoke"
{
  echo "key $key"
  grep -v '^\s*#' "$lockfile" | grep -v '^\s*$'
  echo "patches:"; ( cd "$here/patches" 2>/dev/null && find . -name '*.patch' | sort ) || true
  echo "joined $(date -u +%Y-%m-%dT%H:%M:%SZ) on $(uname -m)"
} > "$join/MANIFEST"
touch "$join/.complete"
rm -rf "$prefix"
mv "$join" "$prefix"
if $with_gdb; then add_gdb; fi

say "total $(( $(date +%s) - total_t0 )) s; toolchain in $prefix"
echo "$prefix"
