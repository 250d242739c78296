#!/usr/bin/env bash
# OpenFOAM reference for the lid-driven cavity of Basa, Quinlan & Lastiwka 2008, whose
# reference solution is an OpenFOAM PISO run on 200 x 200 and 300 x 300 meshes.
#
#   cases/basa_cavity/openfoam/run.sh RE N [WORKDIR]
#
# RE = 100 (to t = 20) or 1000 (to t = 80); N cells per side (a multiple of 10, so that 0.1 time
# units is a whole number of steps). Unit square, lid velocity (1, 0) on y = 1, nu = 1/RE, fluid at
# rest at t = 0. icoFoam (laminar PISO, 2 pressure correctors), Euler in time, central differences
# in space (Gauss linear), fixed dt = 1/N: Courant number 1 at the lid speed, below 1 in every
# cell (the flow next to the lid is slower than the lid; the log's largest was 0.985).
#
# Writes into bench/openfoam_cavity/:
#   openfoam_re<RE>_n<N>_kinetic_energy.csv   t, kinetic_energy = 1/2 int |u|^2 dA (every 0.1)
#   openfoam_re<RE>_n<N>_u_x0.5.csv           y, u on x = 0.5 at the end time (cell rows + walls)
#   openfoam_re<RE>_n<N>_v_y0.5.csv           x, v on y = 0.5 at the end time (cell columns + walls)
# and prints the r.m.s. and max difference from Ghia et al. 1982 (compare_ghia.py).
# Needs Debian's openfoam package (OpenFOAM v1912: icoFoam, blockMesh, postProcess on PATH) and
# python3. Runs on one core at nice 10. The case folder (default /tmp/arksph_openfoam_re<RE>_n<N>)
# is recreated.
set -euo pipefail

re=${1:?usage: run.sh RE N [WORKDIR]}
n=${2:?usage: run.sh RE N [WORKDIR]}
case "$re" in
  100) end=20 ;;
  1000) end=80 ;;
  *) echo "run.sh: RE must be 100 or 1000, got '$re'" >&2; exit 2 ;;
esac
if ! [[ "$n" =~ ^[0-9]+$ ]] || (( n < 10 || n % 10 != 0 )); then
  echo "run.sh: N must be a multiple of 10, at least 10, got '$n'" >&2; exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../../.." && pwd)
out="$repo/bench/openfoam_cavity"
work=${3:-/tmp/arksph_openfoam_re${re}_n${n}}
source "$repo/scripts/openfoam.sh"
mkdir -p "$out"
rm -rf "$work"
mkdir -p "$work/0" "$work/constant" "$work/system"

# Derived numbers: nu, the depth of the one-cell-thick 2D mesh (= dx, cubic cells), dt and the
# number of steps in 0.1 time units.
nu=$(python3 -c "print(repr(1.0 / $re))")
depth=$(python3 -c "print(repr(1.0 / $n))")
dt=$(python3 -c "print(repr(1.0 / $n))")
every=$(( n / 10 ))  # 0.1 / dt

{ foam_header dictionary blockMeshDict
  cat <<EOD
convertToMeters 1;
vertices ((0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 $depth) (1 0 $depth) (1 1 $depth) (0 1 $depth));
blocks (hex (0 1 2 3 4 5 6 7) ($n $n 1) simpleGrading (1 1 1));
edges ();
boundary
(
    movingWall { type wall; faces ((3 7 6 2)); }
    fixedWalls { type wall; faces ((0 4 7 3) (2 6 5 1) (1 5 4 0)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
EOD
} > "$work/system/blockMeshDict"

{ foam_header dictionary controlDict
  cat <<EOD
application icoFoam;
startFrom startTime;
startTime 0;
stopAt endTime;
endTime $end;
deltaT $dt;
writeControl runTime;
writeInterval $end;
purgeWrite 0;
writeFormat ascii;
writePrecision 10;
writeCompression off;
timeFormat general;
timePrecision 6;
runTimeModifiable false;
functions
{
    magSqrU
    {
        type magSqr;
        libs (fieldFunctionObjects);
        field U;
        result magSqrU;
        executeControl timeStep;
        executeInterval $every;
        writeControl none;
    }
    kineticEnergy
    {
        type volFieldValue;
        libs (fieldFunctionObjects);
        fields (magSqrU);
        operation volIntegrate;
        regionType all;
        writeFields false;
        log false;
        executeControl timeStep;
        executeInterval $every;
        writeControl timeStep;
        writeInterval $every;
    }
}
EOD
} > "$work/system/controlDict"

foam_ico_schemes Euler > "$work/system/fvSchemes"

foam_piso_solution 1e-06 0.05 1e-06 > "$work/system/fvSolution"

{ foam_header dictionary transportProperties
  echo "nu $nu;"
} > "$work/constant/transportProperties"

{ foam_header volVectorField U
  cat <<'EOD'
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    movingWall { type fixedValue; value uniform (1 0 0); }
    fixedWalls { type noSlip; }
    frontAndBack { type empty; }
}
EOD
} > "$work/0/U"

{ foam_header volScalarField p
  cat <<'EOD'
dimensions [0 2 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
    movingWall { type zeroGradient; }
    fixedWalls { type zeroGradient; }
    frontAndBack { type empty; }
}
EOD
} > "$work/0/p"

foam_run "$work" blockMesh icoFoam
seconds=$FOAM_SECONDS
foam_run "$work" "postProcess -func writeCellCentres -latestTime"
echo "icoFoam: Re = $re, ${n} x ${n}, t = $end, dt = $dt: ${seconds} s wall"

python3 "$here/extract.py" "$work" "$end" "$depth" \
  "$out/openfoam_re${re}_n${n}_kinetic_energy.csv" "$out/openfoam_re${re}_n${n}_u_x0.5.csv" \
  "$out/openfoam_re${re}_n${n}_v_y0.5.csv"
python3 "$here/compare_ghia.py" "$re" "$out/openfoam_re${re}_n${n}_u_x0.5.csv" "$out/openfoam_re${re}_n${n}_v_y0.5.csv" \
  "$repo/bench/ghia"
