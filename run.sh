#!/usr/bin/env bash
# ./run.sh [CASE] — install what is missing, build Release, then open the studio on CASE when a
# display is available, otherwise run CASE headless into results/<case name>/.
set -euo pipefail
cd "$(dirname "$0")"
source scripts/common.sh

case_file="${1:-sample_cases/default.toml}"
install_dependencies
build_release

if [[ -n "${DISPLAY:-}" && -x build/bin/lbdem-studio ]] && xdpyinfo_ok; then
    echo "Opening lbdem-studio on $case_file"
    exec build/bin/lbdem-studio "$case_file"
fi
echo "No display: running $case_file headless"
build/bin/lbdem run "$case_file"
name=$(build/bin/lbdem info "$case_file" --json >/dev/null && sed -n 's/^name *= *"\(.*\)"/\1/p' "$case_file" | head -n 1)
echo "Outputs are in results/${name:-default}/"
