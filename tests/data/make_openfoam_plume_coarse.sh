#!/bin/sh
# Writes tests/data/openfoam_plume_coarse: the heated plume of
# examples/openfoam/heated_plume.sh computed by OpenFOAM on a coarse mesh
# (20 × 10 × 20 cells, 2 s), reduced to what the import test reads — the
# mesh, T and p at 1 s and 2 s (gzip, as OpenFOAM wrote them), the
# controlDict and the case.foam that VTK's reader opens. Needs Debian's
# openfoam and openfoam-examples; run from the repository root.
set -eu
OUT=tests/data/openfoam_plume_coarse
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
examples/openfoam/heated_plume.sh "$WORK/case" 2 "20 10 20"
rm -rf "$OUT"
mkdir -p "$OUT/system" "$OUT/constant" "$OUT/1" "$OUT/2"
cp "$WORK/case/case.foam" "$OUT/"
cp "$WORK/case/system/controlDict" "$OUT/system/"
cp -r "$WORK/case/constant/polyMesh" "$OUT/constant/"
for time in 1 2; do cp "$WORK/case/$time/T.gz" "$WORK/case/$time/p.gz" "$OUT/$time/"; done
du -sh "$OUT"
