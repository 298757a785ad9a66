#!/usr/bin/env bash
# The fluid solver's GPU-dependent figures in one run (docs/benchmarks-gpu-solver.md):
# ms per step on both backends at 64³, 128³ and 256³ (bench_fluid_step), and
# the live frame rate of hot_plate_plume with its solver at 128³ and 256³ on
# each backend and of pool_caustics with its water on each device. Run from
# the repository root after `./dev.sh test` (or a release build); on a
# machine without a GPU it measures llvmpipe, as the development machine's
# figures do.
#   bench/gpu_solver.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
build=${1:-build/release}
out=${2:-out/gpu-solver}
mkdir -p "$out"

"$build/eikon" info | tee "$out/info.txt"
"$build/bench_fluid_step" --benchmark_counters_tabular=true \
    --benchmark_out="$out/fluid_step.json" --benchmark_out_format=json

# frames/s over frames 2 … N−2 of a run's report (frame 0 compiles shaders,
# frame 1 uploads, the last frame produces no next one).
frames_per_second() {
    grep -o '"frame_ms":[0-9.e+-]*' "$1/report.jsonl" | tail -n +3 | head -n -1 | cut -d: -f2 |
        awk '{ total += $1; n += 1 } END { if (n) printf "%.1f frames/s (%.1f ms a frame over %d frames)\n", 1000 * n / total, total / n, n }'
}

for resolution in 128 256; do
    for device in gpu cpu; do
        run="$out/hot_plate_plume_${device}_${resolution}"
        "$build/eikon" run scenes/hot_plate_plume.json --frames 12 --quiet --force --out "$run" \
            --set sim.device="$device" --set "sim.resolution=[$resolution,$resolution,$resolution]" \
            --set "grid.resolution=[128,128,128]"
        echo "hot_plate_plume, solver ${resolution}³ on the $device: $(frames_per_second "$run")" | tee -a "$out/summary.txt"
    done
done
for device in gpu cpu; do
    run="$out/pool_caustics_water_${device}"
    "$build/eikon" run scenes/pool_caustics.json --frames 12 --quiet --force --out "$run" --set objects.0.device="$device"
    echo "pool_caustics, water on the $device: $(frames_per_second "$run")" | tee -a "$out/summary.txt"
done
