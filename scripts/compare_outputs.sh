#!/bin/sh
# Runs the same scenes with two arksph binaries and compares their outputs byte for byte: the check
# that a refactoring leaves results unchanged.
#   scripts/compare_outputs.sh OLD_BINARY NEW_BINARY OUTDIR
# Scenes: the cavity Re = 100 case to its end, the ISPH spin-down to t = 1, and the Poiseuille case
# with the viscous term implicit (IMEX). Prints one line per scene; exit 1 if any output differs.
set -u
old=$1 new=$2 out=$3
cd "$(dirname "$0")/.."
mkdir -p "$out"
status=0
compare() {  # name, then the run arguments
  name=$1; shift
  for which in old new; do
    binary=$old; [ "$which" = new ] && binary=$new
    rm -rf "$out/$name-$which"
    OMP_NUM_THREADS=1 "$binary" run "$@" --out "$out/$name-$which" --quiet > "$out/$name-$which.log" 2>&1 ||
      echo "$name: $which binary exited $?"
  done
  last=$(ls "$out/$name-old"/particles_*.vtp 2>/dev/null | tail -n 1)
  last=${last##*/}
  if [ -n "$last" ] && cmp -s "$out/$name-old/timeseries.csv" "$out/$name-new/timeseries.csv" &&
     cmp -s "$out/$name-old/$last" "$out/$name-new/$last"; then
    echo "$name: timeseries.csv and $last identical"
  else
    echo "$name: outputs differ"
    status=1
  fi
}
compare cavity_re100 cases/cavity_re100/scene.toml
compare spin_down_t1 cases/spin_down/scene.toml --set time.end=1
compare poiseuille_imex cases/poiseuille/scene.toml --set time.imex=true
exit $status
