#!/usr/bin/env bash
# Every GPU-dependent figure of the benchmark pages in one run, sized for a
# short lease of a GPU machine (docs/benchmarks-gpu.md, "Measuring on a GPU
# machine"):
#  1. image space against the eikonal tracer, frame times of the surface
#     scenes (docs/benchmarks-image-space.md's conventions);
#  2. every scene's eikonal frame (the wavefront where the scene uses it);
#  3. the multiple-scattering lattice, ms per converged frame and
#     iterations at 64³ and 128³ (bench_lattice);
#  4. the fluid solver on both backends and the live loops
#     (bench/gpu_solver.sh);
#  5. eikon accuracy --quick, image space's and the tracer's error against
#     run time on the analytic cases.
# Each step has a time limit, so one that hangs costs only its own share.
# Results go to OUT_DIR, and all but the pictures also to OUT_DIR.tar.gz; a
# summary is printed last.
#   bench/gpu_all.sh [--quick] [BIN_DIR] [OUT_DIR]
# BIN_DIR holds eikon and the bench_ binaries: build/release, or the bin/ of
# tools/bundle-release.sh's archive (with LD_LIBRARY_PATH at its lib/).
# --quick checks the script itself in a few minutes on any machine: tiny
# images and photon counts, the lattice at 64³ only, no solver runs; its
# figures mean nothing.
set -uo pipefail
cd "$(dirname "$0")/.."
quick=()  # extra settings of every eikon run
lattice_filter=.
if [ "${1:-}" = --quick ]; then
    quick=(--set render.width=48 --set render.height=36 --set render.photons=4096 --set render.caustic_map_texels=32)
    lattice_filter='n:64/albedo_pct:50/links:6'
    shift
fi
bin=$(realpath "${1:-build/release}")
out=${2:-out/gpu-all}
mkdir -p "$out/runs"
out=$(realpath "$out")
summary="$out/summary.txt"
: > "$summary"
note() { echo "$*" | tee -a "$summary"; }

# render_ms of frames FIRST … LAST of a report, their median.
median_render_ms() {
    grep -o '"render_ms":[0-9.e+-]*' "$1/report.jsonl" | sed -n "$(($2 + 1)),$(($3 + 1))p" | cut -d: -f2 | sort -g |
        awk '{ v[NR] = $1 } END { if (NR) printf "%.2f", (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; else printf "n/a" }'
}

timeout 60 "$bin/eikon" info | tee "$out/info.txt"

note "## image space against eikonal (render_ms; image space: median of frames 2-4; eikonal: frame 0 static, 1 moving)"
for scene in default glass_sphere_sky pool_caustics twisting_glass deforming_blob; do
    for texels in 256 128; do
        run="$out/runs/${scene}_image_space_${texels}"
        timeout 120 "$bin/eikon" run "scenes/$scene.json" --frames 5 --quiet --force --out "$run" \
            --set render.method=image_space --set render.caustic_map_texels=$texels "${quick[@]}" >/dev/null 2>"$run.log"
        note "$scene image_space ${texels}²: $(median_render_ms "$run" 2 4) ms"
    done
    run="$out/runs/${scene}_eikonal"
    timeout 120 "$bin/eikon" run "scenes/$scene.json" --frames 2 --quiet --force --out "$run" "${quick[@]}" \
        >/dev/null 2>"$run.log"
    frame=1
    case $scene in default | glass_sphere_sky) frame=0 ;; esac
    note "$scene eikonal: $(median_render_ms "$run" $frame $frame) ms"
done

note "## every scene, eikonal (render_ms, median of frames 1-3; frame 0 compiles the shaders)"
for file in scenes/*.json; do
    scene=$(basename "$file" .json)
    run="$out/runs/${scene}_frames"
    timeout 120 "$bin/eikon" run "$file" --frames 4 --quiet --force --out "$run" "${quick[@]}" >/dev/null 2>"$run.log"
    later=$(median_render_ms "$run" 1 3)
    if [ "$later" = 0.00 ]; then  # a static scene renders once
        note "$scene: static, frame 0 $(median_render_ms "$run" 0 0) ms (shaders compiled in it)"
    else
        note "$scene: $later ms (frame 0: $(median_render_ms "$run" 0 0) ms)"
    fi
done

note "## multiple-scattering lattice (bench_lattice)"
timeout 240 "$bin/bench_lattice" --benchmark_filter="$lattice_filter" --benchmark_counters_tabular=true \
    --benchmark_out="$out/lattice.json" --benchmark_out_format=json 2>&1 | tee "$out/lattice.txt" | grep -E "^BM_|^Benchmark" | tee -a "$summary"

note "## fluid solver and live loops (bench/gpu_solver.sh)"
if [ ${#quick[@]} -eq 0 ]; then
    timeout 420 bench/gpu_solver.sh "$bin" "$out/solver" >"$out/solver.log" 2>&1
    cat "$out/solver/summary.txt" 2>/dev/null | tee -a "$summary"
    grep -E "^BM_" "$out/solver.log" | tee -a "$summary"
else
    note "(left out with --quick)"
fi

note "## accuracy against run time (eikon accuracy --quick; last, the one step that may run out of time)"
if [ ${#quick[@]} -eq 0 ]; then
    timeout 150 "$bin/eikon" accuracy --quick --out "$out/accuracy" >"$out/accuracy.log" 2>&1
    note "eikon accuracy: exit $? (report in $out/accuracy)"
else
    note "(left out with --quick)"
fi

# Everything but the pictures in one archive, to carry off a borrowed machine.
tar -czf "$out.tar.gz" -C "$(dirname "$out")" --exclude='*.png' --exclude='*.vti' --exclude='*.vtp' "$(basename "$out")"

echo
echo "=== summary ($summary; reports and logs in $out.tar.gz) ==="
cat "$summary"
