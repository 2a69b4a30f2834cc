#!/usr/bin/env bash
# Builds the bfin-elf toolchain (binutils, C-only gcc with libgcc) and the GNU Blackfin simulator
# (bfin-elf-run) from Debian's source packages, into a cache outside the clone.
#
#   emu/bootstrap.sh                 build if needed; print the toolchain prefix on stdout
#   emu/bootstrap.sh --print-prefix  print where the toolchain is (or would be); build nothing
#   emu/bootstrap.sh --print-key     print the cache key
#
# Cache: $BFIN_TOOLCHAIN_CACHE, default ${XDG_CACHE_HOME:-~/.cache}/bfin-vision-bench/toolchain.
# Each complete toolchain lives in <cache>/<key>, where the key hashes everything that went into
# it: emu/toolchain.lock (the source package versions), this script, emu/patches/*, the host.
# A toolchain is built in <cache>/work-<key> and renamed into place only when complete, so a
# directory named by its key is always whole. A failed stage removes its own build directory;
# stages that finished keep their stamps, so the next run resumes at the failed stage, cleanly.
# Two runs at once serialise on a lock; the second one finds the first one's result.
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
mapfile -t source_pkgs < <(grep -v '^\s*#' "$lockfile" | grep -v '^\s*$')

compute_key() {
  {
    cat "$lockfile" "${BASH_SOURCE[0]}"
    if [ -d "$here/patches" ]; then find "$here/patches" -type f -print0 | sort -z | xargs -0r cat; fi
    uname -m
    cut -d. -f1 /etc/debian_version 2>/dev/null || true
  } | sha256sum | cut -c1-16
}

key=$(compute_key)
prefix="$cache_root/$key"

case "${1:-}" in
  --print-prefix) echo "$prefix"; exit 0 ;;
  --print-key) echo "$key"; exit 0 ;;
  "") ;;
  -h|--help) sed -n '2,17p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
  *) die "unknown option '$1' (try --help)" ;;
esac

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
  "${sudo[@]}" apt-get update -q || die "apt-get update failed"
  "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}" ||
    die "apt-get install failed for: ${missing[*]}"
  mapfile -t missing < <(missing_packages)
  [ ${#missing[@]} -eq 0 ] || die "still missing after apt-get: ${missing[*]}"
}

if toolchain_works "$prefix"; then
  say "toolchain $key is cached in $prefix"
  echo "$prefix"; exit 0
fi

mkdir -p "$cache_root"
exec 9>"$cache_root/.lock-$key"
if ! flock -n 9; then
  say "another bootstrap is building $key; waiting for it"
  flock 9
fi

if [ -f "$prefix/.complete" ]; then
  # Cached but not runnable here: the host libraries the compiler links against are missing.
  stage_t0=$(date +%s)
  say "stage host-packages: start (cached toolchain needs host libraries)"
  ensure_packages
  say "stage host-packages: $(( $(date +%s) - stage_t0 )) s"
  toolchain_works "$prefix" || die "cached toolchain in $prefix does not run; delete it and rerun"
  echo "$prefix"; exit 0
fi
if [ -e "$prefix" ]; then rm -rf "$prefix"; fi   # left without .complete: never trust it

work="$cache_root/work-$key"
stage_dir="$work/prefix"
mkdir -p "$work/stamps" "$work/logs" "$work/build"
export PATH="$stage_dir/bin:$PATH"
summary=()
total_t0=$(date +%s)

# run_stage NAME FUNCTION: skipped if stamped; otherwise runs in a fresh build/NAME directory with
# its output in logs/NAME.log; on failure prints the log's tail and removes the stage's directory.
run_stage() {
  local name=$1 fn=$2 t0 dt log="$work/logs/$1.log"
  if [ -f "$work/stamps/$name" ]; then
    say "stage $name: done by an earlier run, kept"
    summary+=("$(printf '%-12s kept' "$name")")
    return 0
  fi
  say "stage $name: start (log: $log)"
  t0=$(date +%s)
  rm -rf "${work:?}/build/$name"
  mkdir -p "$work/build/$name"
  if ! ( cd "$work/build/$name" && "$fn" ) >"$log" 2>&1; then
    dt=$(( $(date +%s) - t0 ))
    say "stage $name FAILED after ${dt} s; last lines of $log:"
    tail -n 25 "$log" | sed 's/^/    /' >&2
    rm -rf "${work:?}/build/$name"
    exit 1
  fi
  dt=$(( $(date +%s) - t0 ))
  touch "$work/stamps/$name"
  say "stage $name: done in ${dt} s"
  summary+=("$(printf '%-12s %5d s' "$name" "$dt")")
}

src_tarball() {  # the single tarball a glob names, or a clear error
  local matches=( $1 )
  [ -f "${matches[0]}" ] || { echo "source tarball $1 not found" >&2; return 1; }
  echo "${matches[0]}"
}

stage_unpack() {
  local src="$work/src"
  rm -rf "$src"; mkdir -p "$src"
  tar -C "$src" -xf "$(src_tarball '/usr/src/binutils/binutils-*.tar.xz')"
  tar -C "$src" -xf "$(src_tarball /usr/src/gdb.tar.xz)"
  tar -C "$src" -xf "$(src_tarball '/usr/src/gcc-12/gcc-*-dfsg.tar.xz')"
  # From newlib only libgloss's Blackfin headers (MMR names: <blackfin.h>, <defBF537.h>), which
  # the simulator's test suite and bare-metal code include; no C library is built.
  tar -C "$src" -xf "$(src_tarball '/usr/src/newlib/newlib-*.tar.xz')" --wildcards '*/libgloss/bfin/include/*'
  ( cd "$src" && mv binutils-* binutils && mv gcc-* gcc && mv newlib-* newlib && test -d gdb )
  # Debian strips the GFDL manuals from gcc; its own patch lets the build go on without them.
  ( cd "$src/gcc" && patch -p2 < /usr/src/gcc-12/debian/patches/gcc-gfdl-build.diff )
  if [ -d "$here/patches" ]; then
    local p
    for p in "$here"/patches/*.patch; do
      [ -e "$p" ] || continue
      echo "applying $p"; ( cd "$src" && patch -p1 < "$p" )
    done
  fi
  ls "$src"
}

stage_binutils() {
  "$work/src/binutils/configure" --target=$target --prefix="$stage_dir" \
    --disable-nls --disable-werror --disable-gdb --disable-sim --disable-gprofng --disable-gold
  make -j"$jobs"
  make install
}

stage_sim() {
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

stage_gcc() {
  "$work/src/gcc/configure" --target=$target --prefix="$stage_dir" \
    --enable-languages=c --without-headers --with-newlib --disable-multilib --disable-nls \
    --disable-shared --disable-threads --disable-libssp --disable-libquadmath --disable-libgomp \
    --disable-libatomic --disable-lto --disable-decimal-float --disable-werror
  make -j"$jobs" all-gcc all-target-libgcc
  make install-gcc install-target-libgcc
}

stage_headers() {
  mkdir -p "$stage_dir/$target/include"
  cp -a "$work/src/newlib/libgloss/bfin/include/." "$stage_dir/$target/include/"
  echo '#include <blackfin.h>' | "$target-gcc" -mcpu=bf537 -E -x c - >/dev/null
}

stage_smoke() {
  cat > smoke.c <<'EOF'
int twice(int x) { return 2 * x; }
EOF
  cat > start.s <<'EOF'
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
EOF
  "$target-gcc" -O2 -c smoke.c -o smoke.o
  "$target-as" start.s -o start.o
  "$target-ld" start.o smoke.o -o smoke.elf
  "$target-run" smoke.elf
}

ensure_packages_timed() { ensure_packages; }
say "building toolchain $key into $prefix ($jobs jobs)"
t0=$(date +%s)
say "stage packages: start"
ensure_packages_timed
say "stage packages: done in $(( $(date +%s) - t0 )) s"
summary+=("$(printf '%-12s %5d s' packages "$(( $(date +%s) - t0 ))")")

run_stage unpack stage_unpack
run_stage binutils stage_binutils
run_stage sim stage_sim
run_stage gcc stage_gcc
run_stage headers stage_headers
run_stage smoke stage_smoke

{
  echo "key $key"
  grep -v '^\s*#' "$lockfile" | grep -v '^\s*$'
  echo "built $(date -u +%Y-%m-%dT%H:%M:%SZ) on $(uname -m), $jobs jobs"
  printf '%s\n' "${summary[@]}"
} > "$stage_dir/MANIFEST"
touch "$stage_dir/.complete"
mv "$stage_dir" "$prefix"
rm -rf "$work"

say "stage times:"
printf '    %s\n' "${summary[@]}" >&2
say "total $(( $(date +%s) - total_t0 )) s; toolchain in $prefix"
echo "$prefix"
