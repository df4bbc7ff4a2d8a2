#!/usr/bin/env bash
# ./test.sh [ctest args] — install what is missing, build Release, run the CTest suite.
# Long verification runs are labelled `long` and left out; run them with: ./test.sh -L long
set -euo pipefail
cd "$(dirname "$0")"
source scripts/common.sh

install_dependencies
build_release
jobs=$(nproc 2>/dev/null || echo 2)
if [[ " $* " == *" -L "* ]]; then
    exec ctest --test-dir build/release --output-on-failure -j "$jobs" "$@"
fi
exec ctest --test-dir build/release --output-on-failure -j "$jobs" -LE long "$@"
