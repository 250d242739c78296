#!/bin/sh
# chain NAME... : runs the named schemes one after another, single thread, CPU time by /usr/bin/time
S=/work/main/cases/rayleigh_taylor/scene.toml
for name in "$@"; do
  case $name in
    isph_gpps) extra="--set method.scheme=isph-gpps --set method.ppe_divergence=difference --set boundary.free_slip_divergence=true";;
    isph_gpps_vr) extra="--set method.scheme=isph-gpps --set method.ppe_divergence=difference --set boundary.free_slip_divergence=true --set method.gpps_volume_relaxation=0.2";;
    isph) extra="--set method.scheme=isph";;
    wcsph) extra="--set method.scheme=wcsph --set method.density_mode=summation";;
    isph_pw) extra="--set method.scheme=isph --set method.density_correction=pozorski_wawrenczuk";;
  esac
  echo "== $name start $(date -u +%T)"
  OMP_NUM_THREADS=1 /usr/bin/time -v ./arksph_rt run $S --set fluid.spacing=0.008333333333333333 $extra --out $name --quiet > $name.log 2>&1
  echo "== $name exit $? $(date -u +%T)"
done
