#!/bin/sh
# Runs the four schemes of the Rayleigh-Taylor comparison one after the other and draws the
# pictures and the comparison with the OpenFOAM interface.   run.sh ARKSPH OUT_ROOT [SCENE] [--set KEY=VALUE ...]
# e.g. cases/rayleigh_taylor/run.sh build/arksph runs/rt_coarse
#      cases/rayleigh_taylor/run.sh build/arksph runs/rt_120 cases/rayleigh_taylor/scene.toml --set fluid.spacing=0.008333333333333333
set -u
here=$(dirname "$0")
bin=$1; root=$2; shift 2
scene=$here/scene.toml
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then scene=$1; shift; fi
mkdir -p "$root"
run() {  # name, extra --set options
  name=$1; shift
  echo "== $name: $(date -u +%H:%M:%S)"
  "$bin" run "$scene" --out "$root/$name" --quiet "$@" > "$root/$name.log" 2>&1
  echo "   exit $? at $(date -u +%H:%M:%S)"
}
# isph-gpps with the difference-form divergence and free-slip divergence images (Szewc §6): with C&R
# eq. 17 it blew up at t ~ 2 on the coarse lattice.
run isph_gpps "$@" --set method.scheme=isph-gpps --set method.ppe_divergence=difference --set boundary.free_slip_divergence=true
run isph "$@" --set method.scheme=isph
run wcsph "$@" --set method.scheme=wcsph --set method.density_mode=summation
run isph_pw "$@" --set method.scheme=isph --set method.density_correction=pozorski_wawrenczuk
/usr/bin/python3 "$here/plot.py" "$root" isph-gpps="$root/isph_gpps" isph="$root/isph" isph+PW="$root/isph_pw" wcsph="$root/wcsph"
/usr/bin/python3 "$here/summarise.py" "$root" isph_gpps isph isph_pw wcsph
# Interface distances from the OpenFOAM reference at t = 1, 3, 5 (bench/openfoam_rt, 200 x 400).
/usr/bin/python3 "$here/openfoam/compare.py" "$here/../../bench/openfoam_rt/openfoam_rt_n200" --csv "$root/openfoam_compare.csv" \
  isph-gpps="$root/isph_gpps" isph="$root/isph" isph+PW="$root/isph_pw" wcsph="$root/wcsph" | tee "$root/openfoam_compare.md"
