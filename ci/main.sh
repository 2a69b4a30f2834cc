#!/usr/bin/env bash
# The main job: bootstrap the toolchain if needed, build, and run the benchmark on the default
# frame sizes, printing its table.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
build_all
"$build/harness/bfbench" bench "$@"
