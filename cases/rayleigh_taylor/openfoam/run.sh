#!/usr/bin/env bash
# OpenFOAM reference for the Rayleigh-Taylor instability of cases/rayleigh_taylor (Cummins & Rudman
# 1999 section 3.2, Szewc et al. 2012 section 7.2), whose published reference is a level-set figure
# that cannot be read here.
#
#   cases/rayleigh_taylor/openfoam/run.sh N [WORKDIR]
#
# The scene's set-up: box 1 x 2 with no-slip walls, heavy fluid (density 1.8) above light (1) along
# y = 1 - 0.15 sin(2 pi x), gravity (0, -1), the same kinematic viscosity nu = 1/420 in both phases
# (Re = sqrt(L^3 g)/nu = 420), no surface tension, at rest at t = 0. interFoam (VOF with MULES,
# laminar PIMPLE: a momentum predictor, 3 pressure correctors), Euler in time, the step at most 0.01
# and held to Courant number 0.25, N x 2N uniform cells (blockMesh), one cell thick with empty
# front and back. The initial volume fraction is the exact area fraction of the heavy fluid in each
# cell (initial_alpha.py).
# The momentum predictor is needed: without it the pressure correctors alone carry the viscous
# operator, whose splitting error grows with nu dt / dx^2. At 200 x 400 and dt = 0.01 (about 1) the
# largest speed at t = 0.5 came out 44 % low (0.051 against 0.091 with the predictor), and the
# interface fell behind the coarser meshes' (bench/openfoam_rt/README.md).
#
# Writes into bench/openfoam_rt/:
#   openfoam_rt_n<N>_tips.csv              t, bubble_y, spike_y (every 0.5; highest and lowest
#                                          point of the alpha = 0.5 contour)
#   openfoam_rt_n<N>_interface_t<T>.csv    x0, y0, x1, y1: the segments of the alpha = 0.5 contour at
#                                          T = 1, 3, 5 (the format of arksph's interface_NNNNNN.csv)
# Needs Debian's openfoam package (OpenFOAM v1912: interFoam, blockMesh on PATH) and python3 with
# numpy and matplotlib (PYTHON overrides the interpreter). Runs on one core at nice 10. The case
# folder (default /tmp/arksph_openfoam_rt_n<N>) is recreated.
set -euo pipefail

n=${1:?usage: run.sh N [WORKDIR]}
if ! [[ "$n" =~ ^[0-9]+$ ]] || (( n < 10 )); then
  echo "run.sh: N must be a whole number of cells across, at least 10, got '$n'" >&2; exit 2
fi
python=${PYTHON:-python3}
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../../.." && pwd)
out="$repo/bench/openfoam_rt"
work=${2:-/tmp/arksph_openfoam_rt_n${n}}
source "$repo/scripts/openfoam.sh"
mkdir -p "$out"
rm -rf "$work"
mkdir -p "$work/0" "$work/constant" "$work/system"

nu=0.002380952380952381      # 1/420
depth=$("$python" -c "print(repr(1.0 / $n))")
ny=$(( 2 * n ))

foam_walled_box "$n" "$ny" 2 "$depth" > "$work/system/blockMeshDict"

{ foam_header dictionary controlDict
  cat <<'EOD'
application interFoam;
startFrom startTime;
startTime 0;
stopAt endTime;
endTime 5;
deltaT 0.0005;
writeControl adjustableRunTime;
writeInterval 0.5;
purgeWrite 0;
writeFormat ascii;
writePrecision 10;
writeCompression off;
timeFormat general;
timePrecision 6;
runTimeModifiable false;
adjustTimeStep yes;
maxCo 0.25;
maxAlphaCo 0.25;
maxDeltaT 0.01;
EOD
} > "$work/system/controlDict"

{ foam_header dictionary fvSchemes
  cat <<'EOD'
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes
{
    div(rhoPhi,U) Gauss linearUpwind grad(U);
    div(phi,alpha) Gauss vanLeer;
    div(phirb,alpha) Gauss linear;
    div(((rho*nuEff)*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes { default Gauss linear orthogonal; }
interpolationSchemes { default linear; }
snGradSchemes { default orthogonal; }
EOD
} > "$work/system/fvSchemes"

{ foam_header dictionary fvSolution
  cat <<'EOD'
solvers
{
    "alpha.heavy.*"
    {
        nAlphaCorr 2; nAlphaSubCycles 1; cAlpha 1; MULESCorr yes; nLimiterIter 3;
        solver smoothSolver; smoother symGaussSeidel; tolerance 1e-8; relTol 0;
    }
    "pcorr.*" { solver PCG; preconditioner DIC; tolerance 1e-6; relTol 0; }
    p_rgh { solver GAMG; smoother DIC; tolerance 1e-7; relTol 0.05; }
    p_rghFinal { $p_rgh; relTol 0; }
    "U.*" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-7; relTol 0; }
}
PIMPLE { momentumPredictor yes; nOuterCorrectors 1; nCorrectors 3; nNonOrthogonalCorrectors 0;
    pRefCell 0; pRefValue 0; }  // a closed box: the pressure level is pinned
relaxationFactors { equations { ".*" 1; } }
EOD
} > "$work/system/fvSolution"

{ foam_header dictionary transportProperties "constant"
  cat <<EOD
phases (heavy light);
heavy { transportModel Newtonian; nu $nu; rho 1.8; }
light { transportModel Newtonian; nu $nu; rho 1; }
sigma 0;
EOD
} > "$work/constant/transportProperties"

{ foam_header dictionary turbulenceProperties "constant"
  echo "simulationType laminar;"
} > "$work/constant/turbulenceProperties"

{ foam_header uniformDimensionedVectorField g "constant"
  printf 'dimensions [0 1 -2 0 0 0 0];\nvalue (0 -1 0);\n'
} > "$work/constant/g"

{ foam_header volVectorField U "0"
  cat <<'EOD'
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    walls { type noSlip; }
    frontAndBack { type empty; }
}
EOD
} > "$work/0/U"

{ foam_header volScalarField p_rgh "0"
  cat <<'EOD'
dimensions [1 -1 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
    walls { type fixedFluxPressure; value uniform 0; }
    frontAndBack { type empty; }
}
EOD
} > "$work/0/p_rgh"

{ foam_header volScalarField alpha.heavy "0"
  echo "dimensions [0 0 0 0 0 0 0];"
  "$python" "$here/initial_alpha.py" "$n"
  cat <<'EOD'
boundaryField
{
    walls { type zeroGradient; }
    frontAndBack { type empty; }
}
EOD
} > "$work/0/alpha.heavy"

foam_run "$work" blockMesh interFoam
seconds=$FOAM_SECONDS
steps=$(grep -c '^Time = ' "$work/log.interFoam" || true)
echo "interFoam: Rayleigh-Taylor, ${n} x ${ny}, t = 5: ${steps} steps, ${seconds} s wall"
"$python" "$here/extract.py" "$work" "$n" "$out/openfoam_rt_n${n}"
