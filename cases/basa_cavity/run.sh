#!/usr/bin/env bash
# The lid-driven cavity of Basa, Quinlan & Lastiwka 2008 §6.2 with arksph: the batch runs of a
# sweep, then the tables and figures of compare.py against OpenFOAM and Ghia et al. 1982.
#
#   cases/basa_cavity/run.sh RE [RUNS_DIR]
#
# RE = 100: sweep_re100.toml, models A-E x corrections none / shepard / bonet_lok to t = 10;
# RE = 1000: sweep_re1000.toml, four model-correction pairs to t = 30 (the sweeps say why these
# end times, and how to set Basa's 20 and 80).
# One run at a time (OMP_NUM_THREADS=1): 8-30 s of one shared core per unit of time. Finished runs
# are skipped on a second call (arksph batch resumes). Writes cases/basa_cavity/measured/
# re<RE>_results.csv, ke_re<RE>.png, centrelines_re<RE>.png and prints the table.
# Needs build/arksph and a python3 with matplotlib (and vtk for the profile plots); PYTHON
# overrides /usr/bin/python3.
set -euo pipefail

re=${1:?usage: run.sh RE [RUNS_DIR]}
case "$re" in
  100|1000) ;;
  *) echo "run.sh: RE must be 100 or 1000, got '$re'" >&2; exit 2 ;;
esac
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
python=${PYTHON:-/usr/bin/python3}

cd "$root"
# Without RUNS_DIR the sweep's own folder (runs/basa_cavity_re<RE>), so that a plain
# `arksph batch` of the sweep and this script share (and skip) the same runs.
runs=${2:-runs/basa_cavity_re$re}
out=()
[[ -n "${2:-}" ]] && out=(--out "$2")
status=0
OMP_NUM_THREADS=1 ./build/arksph batch "cases/basa_cavity/sweep_re$re.toml" --jobs 1 "${out[@]}" || status=$?
# exit 3: some run blew up or ran out of steps; its rows are part of the comparison.
if (( status != 0 && status != 3 )); then exit "$status"; fi
"$python" "$here/compare.py" "$re" "$runs" "$here/measured"
