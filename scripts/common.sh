# Shared steps of run.sh and test.sh: Debian packages, configure and build.

# Debian packages the build and the tests need (README explains each).
LBDEM_PACKAGES=(build-essential cmake ninja-build pkg-config libeigen3-dev libtomlplusplus-dev
    libcli11-dev nlohmann-json3-dev libhdf5-dev qtbase5-dev libqt5opengl5-dev libvtk9-dev
    libvtk9-qt-dev xvfb xauth x11-utils)

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

# Install the packages that are missing (idempotent); say clearly when that is impossible.
install_dependencies() {
    local missing=()
    for package in "${LBDEM_PACKAGES[@]}"; do
        dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" \
            || missing+=("$package")
    done
    [[ ${#missing[@]} -eq 0 ]] && return 0
    if paraview_conflict; then
        echo "error: Debian's paraview package (python3-paraview) conflicts with python3-vtk9, which" \
             "lbdem's build dependency libvtk9-dev needs, so the two cannot be installed together." \
             "Remove the Debian ParaView yourself (sudo apt-get remove paraview python3-paraview)" \
             "and use ParaView's own binary release from https://www.paraview.org/download/" \
             "(unpack it and run bin/paraview) to open lbdem's results." >&2
        exit 1
    fi
    echo "Installing missing Debian packages: ${missing[*]}"
    local sudo=""
    if [[ $(id -u) -ne 0 ]]; then
        if command -v sudo >/dev/null; then sudo="sudo"; else
            echo "error: packages ${missing[*]} are missing and this user cannot install them (run as root or install sudo)." >&2
            exit 1
        fi
    fi
    if ! { $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null; }; then
        echo "error: apt-get could not install ${missing[*]}; install them by hand and re-run." >&2
        exit 1
    fi
}

# Configure (once) and build the Release tree into build/ with binaries in build/bin.
build_release() {
    local jobs
    jobs=$(nproc 2>/dev/null || echo 2)
    cmake --preset release >/dev/null
    cmake --build --preset release --parallel "$jobs"
}

# True when the X display in $DISPLAY answers.
xdpyinfo_ok() {
    command -v xdpyinfo >/dev/null && xdpyinfo >/dev/null 2>&1
}
