#!/usr/bin/env bash
# The tests: bootstrap the toolchain if needed, build, run every test (ctest).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
build_all
t0=$SECONDS
cd "$build"
ctest --output-on-failure -j "$(nproc)" "$@"
log "tests took $((SECONDS - t0)) s"
