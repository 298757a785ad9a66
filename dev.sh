#!/usr/bin/env bash
# eikon developer entry point. On a fresh Debian 12 machine:
#   ./dev.sh run    install missing packages, build, render scenes/default.json into out/default/
#   ./dev.sh test   install missing packages, build, run every test with ctest;
#                   then build the tests labelled "sanitize" (robustness and
#                   stability suites) under AddressSanitizer + UBSan and run them
#   ./dev.sh debug-test   every test under AddressSanitizer + UBSan
set -euo pipefail
cd "$(dirname "$0")"

install_packages() {
    local missing=()
    local package
    while read -r package; do
        [[ -z "$package" || "$package" == \#* ]] && continue
        if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
            missing+=("$package")
        fi
    done < tools/debian-packages.txt
    ((${#missing[@]} == 0)) && return
    echo "dev.sh: installing ${missing[*]}" >&2
    local sudo=""
    [[ $(id -u) -ne 0 ]] && sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {
    local preset=$1
    cmake --preset "$preset" >/dev/null
    cmake --build --preset "$preset"
}

# llvmpipe uses every core unless told otherwise; keep it to what we have.
export LP_NUM_THREADS="${LP_NUM_THREADS:-$(nproc)}"

case "${1:-}" in
    run)
        install_packages
        build release
        shift
        ./build/release/eikon run scenes/default.json --out out/default --force "$@"
        echo "dev.sh: wrote out/default/frames/frame_00000.png" >&2
        ;;
    test)
        install_packages
        build release
        ctest --preset release -j "$(nproc)"
        cmake --preset debug >/dev/null
        cmake --build --preset debug --target eikon_sanitize_tests
        ctest --preset debug -L sanitize -j "$(nproc)"
        ;;
    debug-test)
        install_packages
        build debug
        ctest --preset debug -j "$(nproc)"
        ;;
    *)
        echo "usage: ./dev.sh run | test | debug-test" >&2
        exit 2
        ;;
esac
