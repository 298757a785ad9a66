#!/bin/sh
# A heated plume, computed by OpenFOAM for scenes/openfoam_plume.json: the
# buoyantPimpleFoam tutorial `hotRoom` (a 600 K square on the floor of a
# closed room of air at 300 K) from Debian's openfoam-examples, scaled to
# a 1 m × 0.5 m × 1 m box with a 10 cm heater, and run laminar on a finer
# mesh, so that the air over the heater is hot enough to see.
#
#   apt-get install --no-install-recommends openfoam openfoam-examples
#   examples/openfoam/heated_plume.sh [CASE_DIR] [END_TIME_S] [CELLS]
#
# CASE_DIR (default out/openfoam_plume) receives the case; its time
# directories (every 0.5 s of simulated time up to END_TIME_S, default 6)
# are what the scene's `volume` reads through VTK's OpenFOAM reader
# (CASE_DIR/case.foam). CELLS (default "40 20 40") is the mesh's cells
# along x, y and z. The solver runs on one core: about a minute for the
# defaults on an unloaded core (32 000 cells, 420 time steps).
set -eu

CASE=${1:-out/openfoam_plume}
END_TIME=${2:-6}
CELLS=${3:-40 20 40}
TUTORIAL=${FOAM_TUTORIAL:-/usr/share/doc/openfoam-examples/examples/heatTransfer/buoyantPimpleFoam/hotRoom}
FOAM_ETC=/usr/share/openfoam/etc

for need in "$FOAM_ETC/controlDict" "$TUTORIAL/system/blockMeshDict"; do
    if [ ! -e "$need" ]; then
        echo "heated_plume.sh: $need is missing; install Debian's openfoam and openfoam-examples" >&2
        exit 2
    fi
done
if [ -e "$CASE" ]; then
    echo "heated_plume.sh: $CASE exists; remove it or name another folder" >&2
    exit 2
fi

# Where Debian's OpenFOAM finds its etc/controlDict (all its programs need).
export WM_PROJECT_DIR="${FOAM_ETC%/etc}"

mkdir -p "$(dirname "$CASE")"
cp -r "$TUTORIAL" "$CASE"
cd "$CASE"
rm -f Allrun Allclean
cp -r 0.orig 0

# The room at a tenth of its size (1 m × 0.5 m × 1 m, y up), the heater the
# tutorial's 1 m square scaled with it; CELLS graded 4 times finer at the
# centre than at the walls (about 1.2 cm across the heater with 40 cells)
# and 20 times finer over the floor than under the ceiling (0.55 cm with
# 20 cells), so the first cells take up the heat of the 600 K face.
sed -i -e 's/^scale   1;/scale   0.1;/' \
    -e "s/(20 10 20) simpleGrading (1 1 1)/($CELLS) simpleGrading (((0.5 0.5 0.25) (0.5 0.5 4)) 20 ((0.5 0.5 0.25) (0.5 0.5 4)))/" \
    system/blockMeshDict
sed -i 's/box (4.5 -1000 4.5) (5.5 1e-5 5.5);/box (0.45 -1 0.45) (0.55 1e-6 0.55);/' system/setFieldsDict
grep -q '^scale   0.1;' system/blockMeshDict && grep -q "($CELLS)" system/blockMeshDict && grep -q 'box (0.45 -1 0.45)' system/setFieldsDict || {
    echo "heated_plume.sh: the tutorial in $TUTORIAL is not the one this script edits (OpenFOAM v1912's)" >&2
    exit 2
}
# Over a 10 cm heater 300 K above the air the plume is laminar: a Rayleigh
# number g·ΔT/T·L³/(ν·α) of about 3e7, far below the 1e9 of transition.
foamDictionary -entry simulationType -set laminar constant/turbulenceProperties > /dev/null
# Time steps at a Courant number of 0.5, written every 0.5 s, compressed.
for entry in "endTime $END_TIME" "deltaT 0.002" "adjustTimeStep yes" "maxCo 0.5" "writeControl adjustableRunTime" \
             "writeInterval 0.5" "writeCompression on"; do
    foamDictionary -entry "${entry%% *}" -set "${entry#* }" system/controlDict > /dev/null
done
touch case.foam  # what VTK's OpenFOAM reader (and ParaView) opens

blockMesh > log.blockMesh 2>&1
setFields > log.setFields 2>&1
buoyantPimpleFoam > log.buoyantPimpleFoam 2>&1
echo "heated_plume.sh: $(grep -c '^Time =' log.buoyantPimpleFoam) time steps; case in $(pwd)"
