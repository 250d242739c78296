#!/usr/bin/env bash
# Scaling of a decomposed run over MPI ranks (docs/scaling.md, bench/README.md).
#
#   bench/mpi_scaling.sh [--build DIR] [--out DIR] [--spacing DX] [--steps S] [--mpirun "CMD"]
#                        [--scheme NAME] [--step F] [--set KEY=VALUE ...]
#
# The doubly periodic box of bench/big_1e6.toml (Wendland C2, h = 2 dx, c = 10) with a vortex field
# periodic on both the unit box and its lower half, u = (sin 2pi x cos 4pi y, -1/2 cos 2pi x sin 4pi y):
# the unit box is two copies of the half box, so its particles do the same work per particle.
# N = 1 / DX^2 particles in the unit box (DX = 0.001: 10^6), N / 2 in the half box. Four runs:
#   weak-1     1 rank,  1 thread,  half box (N/2)
#   ranks-2    2 ranks, 1 thread,  unit box (N)    weak scaling against weak-1, strong against strong-1
#   threads-2  1 rank,  2 threads, unit box (N)    the same cores as ranks-2, shared memory
#   strong-1   1 rank,  1 thread,  unit box (N)
#   pair-1     two weak-1 runs at once, no MPI: what the machine gives two processes of N/2 each
#              (shared memory bandwidth and caches), the ceiling of the weak scaling
# --scheme: method.scheme (default wcsph). Each runs to t = S * F * DX, F = --step (default 0.045:
# about S steps of WCSPH's stability limit 0.25 h / (c + |u|); for isph the viscous limit
# 0.125 h^2 / nu, F = 0.5 DX / nu: 0.07 at DX = 1/700), frames
# only at t = 0 and the end. --set adds a scene key to every run. One rank is a plain process (no mpirun). Time per step: summary.json
# timing.stepping (the steps alone: no set-up, frames or checkpoints) over the steps.
# Memory: the largest resident set (one process: /usr/bin/time; ranks: summary.json
# mpi.max_rss_kb, each rank's getrusage) over the particles of the rank.
# Prints a table and writes OUT/scaling.json. The machine load (uptime) is printed before each run.
set -euo pipefail

build=build
out=bench-runs/mpi_scaling
spacing=0.001
steps=10
scheme=wcsph
step=0.045
mpirun_cmd="mpirun --allow-run-as-root --oversubscribe"
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --spacing) spacing=$2; shift 2 ;;
    --steps) steps=$2; shift 2 ;;
    --mpirun) mpirun_cmd=$2; shift 2 ;;
    --scheme) scheme=$2; shift 2 ;;
    --step) step=$2; shift 2 ;;
    --set) extra+=(--set "$2"); shift 2 ;;
    -h|--help) sed -n '2,26p' "$0"; exit 0 ;;
    *) echo "mpi_scaling.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
here=$(cd "$(dirname "$0")" && pwd)
arksph=$(cd "$build" && pwd)/arksph
scene=$here/big_1e6.toml
mkdir -p "$out"
end=$(python3 -c "print(repr($steps * $step * $spacing))")
common=(--set "fluid.spacing=$spacing" --set "time.end=$end" --set "output.every=0" --quiet --overwrite
        --set "method.scheme=$scheme" "${extra[@]}"
        --set 'initial.velocity=["sin(2*pi*x)*cos(4*pi*y)", "-0.5*cos(2*pi*x)*sin(4*pi*y)"]')
half=(--set 'domain.max=[1.0, 0.5]')

run() {  # name ranks threads [extra args]
  local name=$1 ranks=$2 threads=$3
  shift 3
  echo "== $name: $ranks rank(s) x $threads thread(s); load: $(uptime | sed 's/.*load average: //')"
  rm -rf "${out:?}/$name"
  if [ "$ranks" = 1 ]; then
    OMP_NUM_THREADS=$threads /usr/bin/time -f "%M" -o "$out/$name.rss" \
      "$arksph" run "$scene" --out "$out/$name" "${common[@]}" "$@"
  else
    OMP_NUM_THREADS=$threads $mpirun_cmd -x OMP_NUM_THREADS -n "$ranks" \
      "$arksph" run "$scene" --out "$out/$name" "${common[@]}" "$@"
  fi
}

run weak-1 1 1 "${half[@]}"
run ranks-2 2 1
run threads-2 1 2
run strong-1 1 1
echo "== pair-1: two 1-rank runs at once; load: $(uptime | sed 's/.*load average: //')"
for k in a b; do
  rm -rf "${out:?}/pair-1$k"
  OMP_NUM_THREADS=1 /usr/bin/time -f "%M" -o "$out/pair-1$k.rss" \
    "$arksph" run "$scene" --out "$out/pair-1$k" "${common[@]}" "${half[@]}" > "$out/pair-1$k.log" 2>&1 &
done
wait
echo "== done; load: $(uptime | sed 's/.*load average: //')"

python3 - "$out" <<'EOF'
import json, sys
out = sys.argv[1]
rows = {}
for name, ranks in (("weak-1", 1), ("ranks-2", 2), ("threads-2", 1), ("strong-1", 1)):
    s = json.load(open(f"{out}/{name}/summary.json"))
    t = s["timing"]
    step_s = t["stepping"] / s["steps"]
    if ranks == 1:
        rss = [int(open(f"{out}/{name}.rss").read().split()[-1])]
    else:
        rss = s["mpi"]["max_rss_kb"]
    per_rank = s["particles"] / ranks
    rows[name] = dict(particles=s["particles"], ranks=ranks, steps=s["steps"], wall=s["wall_seconds"],
                      stepping=t["stepping"], step_seconds=step_s, max_rss_kb=rss,
                      bytes_per_particle=[1024.0 * r / per_rank for r in rss],
                      halo_exchanges=s["mpi"].get("halo_exchanges"), mpi_seconds=s["mpi"].get("seconds"))
w1, r2, t2, s1 = (rows[k] for k in ("weak-1", "ranks-2", "threads-2", "strong-1"))
pair = [json.load(open(f"{out}/pair-1{k}/summary.json")) for k in "ab"]
pair_step = max(p["timing"]["stepping"] / p["steps"] for p in pair)
summary = {
    "weak_efficiency": w1["step_seconds"] / r2["step_seconds"],
    "strong_efficiency": s1["step_seconds"] / (2 * r2["step_seconds"]),
    "threads_over_ranks": t2["step_seconds"] / r2["step_seconds"],
    "pair_step_seconds": pair_step,
    "pair_efficiency": w1["step_seconds"] / pair_step,
    "memory_ratio_max_rank": max(r2["bytes_per_particle"]) / w1["bytes_per_particle"][0],
    "memory_ratio_per_rank": [b / w1["bytes_per_particle"][0] for b in r2["bytes_per_particle"]],
}
print(f"{'run':10} {'N':>9} {'ranks':>5} {'steps':>5} {'wall s':>8} {'s/step':>8} {'max RSS MB (per rank)':>24} {'B/particle':>16}")
for k, r in rows.items():
    rss = ", ".join(f"{x / 1024:.0f}" for x in r["max_rss_kb"])
    bpp = ", ".join(f"{x:.0f}" for x in r["bytes_per_particle"])
    print(f"{k:10} {r['particles']:>9} {r['ranks']:>5} {r['steps']:>5} {r['wall']:>8.1f} {r['step_seconds']:>8.3f} {rss:>24} {bpp:>16}")
print(f"weak efficiency (weak-1 / ranks-2, per step): {summary['weak_efficiency']:.2f}")
print(f"two 1-rank runs at once: {pair_step:.3f} s/step (the slower), efficiency {summary['pair_efficiency']:.2f}: the machine's ceiling")
print(f"strong efficiency (strong-1 / (2 x ranks-2)): {summary['strong_efficiency']:.2f}")
print(f"1 rank x 2 threads / 2 ranks x 1 thread, time per step: {summary['threads_over_ranks']:.2f}")
print("memory per particle, ranks-2 / weak-1: max rank {:.2f}, per rank {}".format(
    summary["memory_ratio_max_rank"], ", ".join(f"{x:.2f}" for x in summary["memory_ratio_per_rank"])))
json.dump({"runs": rows, "summary": summary}, open(f"{out}/scaling.json", "w"), indent=1)
EOF
