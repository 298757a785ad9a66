#!/usr/bin/env bash
# Scale-out figures of docs/scale-out.md, measured with the eikon binary:
#  - frames per minute of a 24-frame OpenVDB volume sequence, one process
#    and `mpirun -n 2 ... --distribute frames`;
#  - photons per second of the default scene at 2^22 photons (photon
#    estimator), one process and `mpirun -n 2 ... --distribute photons`
#    (the photon stage's wall time from report.jsonl, and the whole run's).
# Every rank, and the single process it is compared with, gets one
# llvmpipe thread (LP_NUM_THREADS=1); the single process is also run with
# two, as a user without MPI would. The sequence is made first by eikon
# itself: the heat-shimmer plume's temperature exported for 24 frames.
# Usage: bench/scale_out.sh [build/release/eikon] [work folder]
set -euo pipefail
cd "$(dirname "$0")/.."
EIKON=$(realpath "${1:-build/release/eikon}")
WORK=${2:-build/scale_out}
mkdir -p "$WORK"
WORK=$(realpath "$WORK")
MPIRUN=(mpirun --bind-to core)
[ "$(id -u)" = 0 ] && MPIRUN+=(--allow-run-as-root)

seconds() { date +%s.%N; }
elapsed() { awk -v now="$(seconds)" -v start="$1" 'BEGIN { print now - start }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { print a / b }'; }
# The photon stage's wall time (ms) in the first line of a report.
photon_ms() { grep -o '{"ms":[0-9.e+-]*,"name":"photons"' "$1" | head -1 | sed 's/{"ms":\([^,]*\),.*/\1/'; }

echo "# the sequence: 24 frames of the heat-shimmer plume's temperature"
"$EIKON" run scenes/hot_plate_plume.json --frames 24 --quiet --force --out "$WORK/source" \
    --set export.vdb.enabled=true --set 'export.vdb.fields=["temperature"]' --set render.width=64 \
    --set render.height=48
# The heat-shimmer scene with the sequence for its medium. The exported
# kelvin are absolute and the import adds them to its ambient temperature:
# a hotter plume than the source's, whose box shows as faint lines in the
# picture; it changes nothing of what a frame costs.
sed -e '/"sim": {/,$d' scenes/hot_plate_plume.json > "$WORK/volume.json"
{
    echo "  \"volume\": {\"path\": \"$WORK/source/vdb/fields_#####.vdb\", \"frame_start\": 0,"
    echo "             \"frame_time\": 0.04, \"grids\": {\"density\": \"\", \"temperature\": \"temperature\"}}"
    echo "}"
} >> "$WORK/volume.json"

run_frames() {  # label, extra run options, command...
    local label=$1 extra=$2
    shift 2
    local start t
    start=$(seconds)
    # shellcheck disable=SC2086
    "$@" run "$WORK/volume.json" --frames 24 --quiet --force --out "$WORK/frames" $extra >/dev/null
    t=$(elapsed "$start")
    printf '| %s | %.1f | %.1f |\n' "$label" "$t" "$(ratio 1440 "$t")"
}

run_photons() {  # label, extra run options, command...
    local label=$1 extra=$2
    shift 2
    local start t ms
    start=$(seconds)
    # shellcheck disable=SC2086
    "$@" run scenes/default.json --quiet --force --out "$WORK/photons" $extra \
        --set 'tracer.estimator="photons"' --set render.photons=4194304 >/dev/null
    t=$(elapsed "$start")
    ms=$(photon_ms "$WORK/photons/report.jsonl")
    printf '| %s | %.0f | %.2f | %.1f |\n' "$label" "$ms" "$(ratio 4194.304 "$ms")" "$t"
}

# One measurement four ways: one process with two and with one llvmpipe
# thread, one rank, and two ranks sharing the run by `distribution`.
each_configuration() {  # distribution, measurement
    LP_NUM_THREADS=2 "$2" "1 process, 2 llvmpipe threads" "" "$EIKON"
    LP_NUM_THREADS=1 "$2" "1 process, 1 llvmpipe thread" "" "$EIKON"
    LP_NUM_THREADS=1 "$2" "1 rank (mpirun -n 1)" "" "${MPIRUN[@]}" -n 1 -x LP_NUM_THREADS "$EIKON"
    LP_NUM_THREADS=1 "$2" "2 ranks, --distribute $1" "--distribute $1" "${MPIRUN[@]}" -n 2 -x LP_NUM_THREADS "$EIKON"
}

echo
echo "| volume sequence, 24 frames | wall (s) | frames per minute |"
echo "| --- | --- | --- |"
each_configuration frames run_frames
echo
echo "| default scene, 2^22 photons | photon stage (ms) | M photons/s | whole run (s) |"
echo "| --- | --- | --- | --- |"
each_configuration photons run_photons
