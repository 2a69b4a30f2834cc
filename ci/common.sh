# Shared by ci/main.sh and ci/test.sh: host packages, the toolchain, the build.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BVB_BUILD_DIR:-$root/build}

log() { printf '[ci] %s\n' "$*" >&2; }

host_packages() {
  # libpng-dev: .png frames in and out; chromium: the profile page's test loads it in a
  # headless browser.
  local pkgs=(cmake ninja-build g++ libgtest-dev libgmock-dev libpng-dev chromium) missing=()
  for p in "${pkgs[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  log "installing ${missing[*]}"
  local sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get update -q
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
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
