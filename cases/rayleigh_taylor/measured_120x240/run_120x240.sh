#!/bin/sh
# The 120 x 240 runs of this folder's table: one scheme per process, single-threaded, each under
# /usr/bin/time -v so that its log ends with the CPU time; run two of these scripts side by side on
# 2 cores.   run_120x240.sh ARKSPH OUT_DIR NAME...   NAME: isph_gpps isph wcsph isph_pw isph_pw_newton isph_gpps_vr
# e.g. cases/rayleigh_taylor/measured_120x240/run_120x240.sh build/arksph runs/rt120 isph_pw isph_gpps
# Then: python3 cases/rayleigh_taylor/plot.py OUT_DIR isph-gpps=OUT_DIR/isph_gpps ... and summarise.py.
set -u
here=$(cd "$(dirname "$0")" && pwd)
bin=$1; out=$2; shift 2
scene=$here/../scene.toml
mkdir -p "$out"
for name in "$@"; do
  case $name in
    isph_gpps) extra="--set method.scheme=isph-gpps --set method.ppe_divergence=difference --set boundary.free_slip_divergence=true";;
    isph_gpps_vr) extra="--set method.scheme=isph-gpps --set method.ppe_divergence=difference --set boundary.free_slip_divergence=true --set method.gpps_volume_relaxation=0.2";;
    isph) extra="--set method.scheme=isph";;
    wcsph) extra="--set method.scheme=wcsph --set method.density_mode=summation";;
    isph_pw) extra="--set method.scheme=isph --set method.density_correction=pozorski_wawrenczuk";;
    isph_pw_newton) extra="--set method.scheme=isph --set method.density_correction=pozorski_wawrenczuk --set method.correction_solver=newton";;
    *) echo "run_120x240.sh: unknown scheme name '$name'" >&2; exit 2;;
  esac
  echo "== $name start $(date -u +%T)"
  # shellcheck disable=SC2086
  OMP_NUM_THREADS=1 /usr/bin/time -v "$bin" run "$scene" --set fluid.spacing=0.008333333333333333 $extra \
    --out "$out/$name" --quiet > "$out/$name.log" 2>&1
  echo "== $name exit $? $(date -u +%T)"
done
