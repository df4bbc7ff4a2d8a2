#!/usr/bin/env bash
# Fail when a C++ source differs from .clang-format (clang-format 14, Debian 12's; installed when
# missing). Run from anywhere; prints the files that differ.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v clang-format >/dev/null; then
    sudo=""
    [[ $(id -u) -ne 0 ]] && command -v sudo >/dev/null && sudo="sudo"
    { $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq clang-format >/dev/null; } \
        || { echo "error: clang-format is missing and could not be installed (apt-get install clang-format)." >&2; exit 1; }
fi
mapfile -t files < <(git ls-files '*.cpp' '*.h')
if ! clang-format --dry-run --Werror "${files[@]}" 2>/tmp/lbdem-format.$$; then
    grep -o '^[^:]*:[0-9]*:[0-9]*: error' /tmp/lbdem-format.$$ | cut -d: -f1 | sort -u | sed 's/^/not formatted: /' >&2
    rm -f /tmp/lbdem-format.$$
    echo "error: run clang-format -i on the files above (the style is .clang-format)." >&2
    exit 1
fi
rm -f /tmp/lbdem-format.$$
echo "format: ${#files[@]} files match .clang-format"
