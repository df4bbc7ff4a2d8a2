#!/usr/bin/env bash
# ./run.sh [CASE] — install what is missing, build Release, then open the studio on CASE when a
# display is available, otherwise run CASE headless into results/<case name>/.
set -euo pipefail
cd "$(dirname "$0")"
source scripts/common.sh

# Debian 12's paraview package cannot be installed beside libvtk9-dev: its python3-paraview
# conflicts with python3-vtk9, which libvtk9-dev depends on. True when this machine has that
# conflict: the Debian ParaView is installed, or apt would have to remove a package to install
# the VTK build dependency. Only looks; never installs or removes anything.
paraview_conflict() {
    local package
    for package in paraview python3-paraview; do
        dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" && return 0
    done
    dpkg-query -W -f='${Status}' libvtk9-dev 2>/dev/null | grep -q "install ok installed" && return 1
    command -v apt-get >/dev/null || return 1
    local plan
    plan=$(apt-get install --simulate -qq libvtk9-dev libvtk9-qt-dev 2>/dev/null || true)
    grep -q '^Remv .*paraview' <<<"$plan"
}

if paraview_conflict; then
    echo "error: Debian's paraview package (python3-paraview) conflicts with python3-vtk9, which" \
         "lbdem's build dependency libvtk9-dev needs, so the two cannot be installed together." \
         "Remove the Debian ParaView yourself (sudo apt-get remove paraview python3-paraview)" \
         "and use ParaView's own binary release from https://www.paraview.org/download/" \
         "(unpack it and run bin/paraview) to open lbdem's results." >&2
    exit 1
fi

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
