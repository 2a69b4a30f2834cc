# Shared by ci/main.sh and ci/test.sh: host packages, the toolchain, the build.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BVB_BUILD_DIR:-$root/build}

log() { printf '[ci] %s\n' "$*" >&2; }

missing_packages() {
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}

apt_install() {
  local sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get update -q &&
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends "$@"
}

host_packages() {
  local missing
  # libpng-dev: .png frames in and out; chromium: the profile page's test loads it in a
  # headless browser.
  missing=$(missing_packages cmake ninja-build g++ libgtest-dev libgmock-dev libpng-dev chromium)
  if [ -n "$missing" ]; then
    log "installing" $missing
    apt_install $missing
  fi
  # clang and its libFuzzer runtime build the fuzz targets (fuzz/). Without them only the fuzz
  # tests are skipped (ctest says so), so a failed install is reported, not fatal.
  missing=$(missing_packages clang libclang-rt-14-dev)
  if [ -n "$missing" ]; then
    log "installing" $missing "(fuzz targets)"
    apt_install $missing || log "could not install" $missing": the fuzz tests will be skipped"
  fi
}

build_all() {
  local t0=$SECONDS
  host_packages
  log "toolchain (emu/bootstrap.sh)"
  toolchain=$("$root/emu/bootstrap.sh")
  log "configure and build in $build"
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBFIN_TOOLCHAIN_DIR="$toolchain" >/dev/null
  cmake --build "$build" -j "$(nproc)"
  log "set-up and build took $((SECONDS - t0)) s"
}
