#!/usr/bin/env bash
# OpenFOAM reference for the vortex spin-down of Cummins & Rudman 1999 §3.1 (their finite-difference
# "exact projection" curve of Figs. 5 and 7).
#
#   cases/spin_down/openfoam/run.sh N [WORKDIR]
#
# The scene of ../scene.toml: unit box, no-slip walls, nu = 1/420, density 1, the fluid starting in
# rigid rotation u = 0.25 (y - 0.5), v = 0.25 (0.5 - x), to t = 10. icoFoam (laminar PISO, 2
# pressure correctors) on N x N square cells, second-order backward differences in time, central
# differences in space, fixed dt = 1/N (Courant number below 0.18: the largest speed is 0.177, at
# the corners at t = 0). N: a multiple of 10, at least 20.
#
# Writes into bench/openfoam_spin_down/:
#   openfoam_n<N>_history.csv   t, max_speed (largest cell speed), kinetic_energy (1/2 int |u|^2 dA), every 0.5
#   openfoam_n<N>_velocity_t8.csv   x, y, u, v at t = 8 on a 50 x 50 grid of block means (N / 50 cells a side;
#                                   written only when 50 divides N)
# Needs Debian's openfoam package (icoFoam, blockMesh on PATH) and python3 with numpy ($PYTHON to choose another). One core at
# nice 10. The case folder (default /tmp/arksph_openfoam_spin_down_n<N>) is recreated.
set -euo pipefail

n=${1:?usage: run.sh N [WORKDIR]}
if ! [[ "$n" =~ ^[0-9]+$ ]] || (( n < 20 || n % 10 != 0 )); then
  echo "run.sh: N must be a multiple of 10, at least 20, got '$n'" >&2; exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../../.." && pwd)
out="$repo/bench/openfoam_spin_down"
work=${2:-/tmp/arksph_openfoam_spin_down_n${n}}
python=${PYTHON:-python3}
source "$repo/scripts/openfoam.sh"
mkdir -p "$out"
rm -rf "$work"
mkdir -p "$work/0" "$work/constant" "$work/system"

depth=$("$python" -c "print(repr(1.0 / $n))")
dt=$depth

foam_walled_box "$n" "$n" 1 "$depth" > "$work/system/blockMeshDict"

{ foam_header dictionary controlDict
  cat <<EOD
application icoFoam;
startFrom startTime;
startTime 0;
stopAt endTime;
endTime 10;
deltaT $dt;
writeControl runTime;
writeInterval 0.5;
purgeWrite 0;
writeFormat ascii;
writePrecision 10;
writeCompression off;
timeFormat general;
timePrecision 6;
runTimeModifiable false;
EOD
} > "$work/system/controlDict"

foam_ico_schemes backward > "$work/system/fvSchemes"

foam_piso_solution 1e-08 0.01 1e-09 > "$work/system/fvSolution"

{ foam_header dictionary transportProperties
  echo "nu $("$python" -c 'print(repr(1.0 / 420.0))');"
} > "$work/constant/transportProperties"

{ foam_header volVectorField U
  echo "dimensions [0 1 -1 0 0 0 0];"
  "$python" "$here/extract.py" initial "$n"
  cat <<'EOD'
boundaryField
{
    walls { type noSlip; }
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
    walls { type zeroGradient; }
    frontAndBack { type empty; }
}
EOD
} > "$work/0/p"

foam_run "$work" blockMesh icoFoam
echo "icoFoam: spin-down, ${n} x ${n}, t = 10, dt = $dt: ${FOAM_SECONDS} s wall"
"$python" "$here/extract.py" history "$work" "$n" "$out/openfoam_n${n}_history.csv" "$out/openfoam_n${n}_velocity_t8.csv"
