#!/bin/sh
# BM_RhsEval of two bench binaries run in turns, so that both see the same machine load:
#   bench/interleave_rhs.sh OLD_BENCH NEW_BENCH [ROUNDS] [THREADS] [FILTER]
# Prints, per benchmark, max / p90 / median of the rates (M particle evaluations / s) of each binary
# and the ratios new/old of the maxima and the medians.
set -u
old=$1 new=$2 rounds=${3:-4} threads=${4:-2} filter=${5:-'BM_RhsEval/(50|100|240)/'}
dir=$(mktemp -d)
for r in $(seq "$rounds"); do
  for which in old new; do
    binary=$old; [ "$which" = new ] && binary=$new
    OMP_NUM_THREADS=$threads "$binary" --benchmark_filter="$filter" --benchmark_min_time=0.05 \
      --benchmark_repetitions=10 --benchmark_format=json > "$dir/$which.$r.json" 2>/dev/null
  done
done
python3 - "$dir" <<'PY'
import glob, json, statistics, sys
rates = {}
for path in glob.glob(sys.argv[1] + "/*.json"):
    which = path.rsplit("/", 1)[1].split(".")[0]
    for b in json.load(open(path))["benchmarks"]:
        if b.get("run_type") == "iteration":
            rates.setdefault((b["run_name"], which), []).append(b["items_per_second"] / 1e6)
for name in sorted({k[0] for k in rates}):
    old, new = sorted(rates[(name, "old")]), sorted(rates[(name, "new")])
    def summary(v):
        return f"{v[-1]:.2f} / {v[int(0.9 * (len(v) - 1))]:.2f} / {statistics.median(v):.2f}"
    print(f"{name}  old {summary(old)}  new {summary(new)}  new/old max {new[-1] / old[-1]:.3f}"
          f" median {statistics.median(new) / statistics.median(old):.3f}")
PY
rm -rf "$dir"
