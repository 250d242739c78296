#!/bin/sh
# The Taylor-Green table of README.md: every scheme with and without regularisation, Re = 100 and
# 1000, 50 x 50 and 100 x 100, to t = 2. Writes results.csv (relative L1, peak-speed and amplitude
# errors at t = 1 and t = 2, wall time)
# and, through plot.py, taylor_green.png.
#   usage: cases/taylor_green/run.sh [ARKSPH_BINARY] [OUTPUT_ROOT]
# SCHEMES="wcsph" (a subset of isph isph-gpps wcsph) re-runs those schemes' rows and keeps the others.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
bin=${1:-$here/../../build/arksph}
root=${2:-runs/taylor_green_table}
mkdir -p "$root"
csv=$here/results.csv
schemes=${SCHEMES:-isph isph-gpps wcsph}
header="scheme,regularisation,re,n,l1_t1,peak_t1,l1_t2,peak_t2,wall_seconds,exit_code,amplitude_t1,amplitude_t2"
kept=""
[ -f "$csv" ] && kept=$(grep -v "^scheme," "$csv" | grep -v -E "^($(echo $schemes | tr ' ' '|'))," || true)
echo "$header" > "$csv"
[ -n "$kept" ] && echo "$kept" >> "$csv"
for re in 100 1000; do
  nu=$(python3 -c "print(1.0/$re)")
  decay="exp(-8*pi^2*$nu*t)"
  exact="[\"-cos(2*pi*x)*sin(2*pi*y)*$decay\", \"sin(2*pi*x)*cos(2*pi*y)*$decay\"]"
  for n in 50 100; do
    dx=$(python3 -c "print(1.0/$n)")
    for scheme in $schemes; do
      for reg in default none; do
        out=$root/${scheme}_${reg}_re${re}_n${n}
        off=""
        [ "$reg" = none ] && off="--set method.regularisation=none --set method.density_diffusion=none"
        code=0
        "$bin" run "$here/scene.toml" --out "$out" --overwrite --quiet --set output.every=1 \
          --set method.scheme=$scheme --set fluid.viscosity=$nu --set fluid.spacing=$dx \
          --set "metrics.exact_velocity=$exact" --set time.end=2 $off || code=$?
        ${PYTHON:-/usr/bin/python3} "$here/summarise.py" "$out" "$scheme" "$reg" "$re" "$n" "$code" >> "$csv"
      done
    done
  done
done
${PYTHON:-/usr/bin/python3} "$here/plot.py" "$csv" "$here/taylor_green.png"
