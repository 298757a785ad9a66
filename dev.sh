#!/usr/bin/env bash
# eikon developer entry point. On a fresh Debian 12 machine:
#   ./dev.sh run    install missing packages, build, fill the shader cache
#                   (eikon warm-shaders), render scenes/default.json into out/default/
#   ./dev.sh test   install missing packages, build, run every test with ctest;
#                   then build the tests labelled "sanitize" (robustness and
#                   stability suites) under AddressSanitizer + UBSan and run them
#   ./dev.sh debug-test   every test under AddressSanitizer + UBSan
#   ./dev.sh fuzz [SECONDS]   build the libFuzzer targets (clang, ASan + UBSan) and
#                   run each for SECONDS (default 20); fails on any crash, leak or timeout
#   ./dev.sh fuzz-check   the same targets, reproducibly: committed seeds, then a
#                   fixed number of mutations from a fixed random seed (CI runs it)
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

# build PRESET [TARGET…]: configure and build the preset's targets, or only
# the ones named.
build() {
    local preset=$1
    shift
    cmake --preset "$preset" >/dev/null
    if (($# > 0)); then
        cmake --build --preset "$preset" --target "$@"
    else
        cmake --build --preset "$preset"
    fi
}

# llvmpipe uses every core unless told otherwise; keep it to what we have.
export LP_NUM_THREADS="${LP_NUM_THREADS:-$(nproc)}"

# Each fuzzer's seeds: the project's own scenes and meshes, and the hostile
# corpus's files of its kind, and what the fuzzers found before
# (tests/hostile/found, each a regression). What a run finds worth keeping goes to
# build/fuzz/corpus/<target>; a crashing input to build/fuzz/findings/.
fuzz_seeds() {
    case "$1" in
        fuzz_scene) echo scenes tests/hostile/scenes ;;
        fuzz_mesh_*) echo scenes/meshes tests/hostile/files/meshes tests/hostile/found ;;
        fuzz_vdb) echo tests/hostile/files/vdb tests/hostile/found ;;
        fuzz_image) echo tests/hostile/files/images tests/data tests/hostile/found ;;
    esac
}

readonly FUZZ_TARGETS="fuzz_scene fuzz_mesh_obj fuzz_mesh_ply fuzz_mesh_off fuzz_mesh_stl fuzz_vdb fuzz_image"
readonly FUZZ_CHECK_RUNS=2000  # mutations a target, in fuzz-check

# run_fuzzer TARGET CORPUS LIBFUZZER-LIMITS...: one target from its seeds,
# new inputs kept in CORPUS; fails on any crash, leak or timeout.
run_fuzzer() {
    local target=$1 corpus=$2
    shift 2
    mkdir -p "$corpus" build/fuzz/findings
    # shellcheck disable=SC2046  # the seed folders are separate arguments
    ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
        "build/fuzz/$target" "$@" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
        -print_final_stats=1 -artifact_prefix="build/fuzz/findings/$target-" "$corpus" $(fuzz_seeds "$target") \
        2> "build/fuzz/$target.log" || { tail -n 60 "build/fuzz/$target.log" >&2; exit 1; }
    grep -E "^stat::(number_of_executed_units|average_exec_per_sec|new_units_added|peak_rss_mb)|cov: " \
        "build/fuzz/$target.log" | tail -n 5 >&2
}

# A search: each target for SECONDS, growing build/fuzz/corpus.
run_fuzzers() {
    local seconds=$1
    [[ "$seconds" =~ ^[1-9][0-9]*$ ]] || { echo "dev.sh: fuzz takes a whole number of seconds, not '$seconds'" >&2; exit 2; }
    build fuzz
    local target
    for target in $FUZZ_TARGETS; do
        echo "dev.sh: $target for ${seconds} s" >&2
        run_fuzzer "$target" "build/fuzz/corpus/$target" -max_total_time="$seconds"
    done
}

# A check, not a search: each target replays its committed seeds (every
# earlier finding among them) exactly, then tries a fixed number of
# mutations from a fixed random seed, starting from no corpus of its own
# (close to, not bit-for-bit, the same inputs each run: coverage feedback
# varies slightly). CI runs it.
check_fuzzers() {
    build fuzz
    local target
    for target in $FUZZ_TARGETS; do
        echo "dev.sh: $target, seeds and ${FUZZ_CHECK_RUNS} mutations" >&2
        rm -rf "build/fuzz/check/$target"
        run_fuzzer "$target" "build/fuzz/check/$target" -seed=1 -runs="$FUZZ_CHECK_RUNS"
    done
}
case "${1:-}" in
    run)
        install_packages
        # The command line alone, no tests before the first picture; then the
        # default scene's shaders into the driver's cache (eikon warm-shaders,
        # once per build of eikon), so that the run below starts warm.
        build release eikon eikon_shader_cache
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
    fuzz)
        install_packages
        run_fuzzers "${2:-20}"
        ;;
    fuzz-check)
        install_packages
        check_fuzzers
        ;;
    debug-test)
        install_packages
        build debug
        ctest --preset debug -j "$(nproc)"
        ;;
    *)
        echo "usage: ./dev.sh run | test | debug-test | fuzz [SECONDS] | fuzz-check" >&2
        exit 2
        ;;
esac
