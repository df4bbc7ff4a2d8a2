# Shared steps of run.sh and test.sh: Debian packages, configure and build.

# Debian packages the build and the tests need (README explains each).
LBDEM_PACKAGES=(build-essential cmake ninja-build pkg-config libeigen3-dev libtomlplusplus-dev
    libcli11-dev nlohmann-json3-dev libhdf5-dev qtbase5-dev libqt5opengl5-dev libvtk9-dev
    libvtk9-qt-dev xvfb xauth x11-utils)

# Install the packages that are missing (idempotent); say clearly when that is impossible.
install_dependencies() {
    local missing=()
    for package in "${LBDEM_PACKAGES[@]}"; do
        dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" \
            || missing+=("$package")
    done
    [[ ${#missing[@]} -eq 0 ]] && return 0
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
