#!/bin/sh
# Wall-time ratio wcsph : isph : isph + P-W on the cavity at equal N (Szewc et al. 2012 §7.1, §9):
# N = 3600, t in [0, 3], one thread each, CPU seconds from /usr/bin/time.
# usage: cases/cavity_re1000/wall_time_ratio.sh ARKSPH OUTDIR [--set KEY=VALUE ...]
set -e
if [ $# -lt 2 ]; then echo "usage: $0 ARKSPH OUTDIR [--set KEY=VALUE ...]" >&2; exit 2; fi
B=$1; O=$2; shift 2
S="$(cd "$(dirname "$0")" && pwd)/scene.toml"
mkdir -p "$O"
: > "$O/times.txt"
for name in isph isph_pw wcsph; do
  case $name in
    isph) extra="" ;;
    isph_pw) extra="--set method.density_correction=pozorski_wawrenczuk" ;;
    wcsph) extra="--set method.scheme=wcsph --set method.background_pressure=1 --set boundary.free_slip_divergence=true" ;;
  esac
  # shellcheck disable=SC2086
  OMP_NUM_THREADS=1 /usr/bin/time -f "$name %U" -a -o "$O/times.txt" "$B" run "$S" --set time.end=3 \
    --set output.every=3 --set output.directory="$O/$name" $extra "$@" -q > "$O/$name.log" 2>&1
done
awk '{t[$1] = $2} END {printf "CPU s: isph %.1f, isph+PW %.1f, wcsph %.1f; wcsph/isph %.2f (Szewc ~7), (isph+PW)/isph %.2f (Szewc ~2)\n",
  t["isph"], t["isph_pw"], t["wcsph"], t["wcsph"] / t["isph"], t["isph_pw"] / t["isph"]}' "$O/times.txt"
