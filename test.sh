#!/usr/bin/env bash
# ./test.sh [ctest args] — install what is missing, build Release, run the CTest suite.
# Long verification runs are labelled `long` and left out; run them with: ./test.sh -L long
set -euo pipefail
cd "$(dirname "$0")"
source scripts/common.sh

# ctest runs two tests at once on two cores: OpenMP threads must sleep rather than spin while
# they wait, or each test slows the other down up to tenfold. (A lone run is faster spinning,
# which is why run.sh keeps OpenMP's default.)
export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-passive}"

install_dependencies
build_release
jobs=$(nproc 2>/dev/null || echo 2)
if [[ " $* " == *" -L "* ]]; then
    exec ctest --test-dir build/release --output-on-failure -j "$jobs" "$@"
fi
exec ctest --test-dir build/release --output-on-failure -j "$jobs" -LE long "$@"
