#!/usr/bin/python3
"""Log-log plot of Poisson solve time and iterations against N from a CSV (n,solver,seconds,iterations;
lines starting with # are comments), e.g. bench/ppe_scaling.csv.

usage: plot_ppe_scaling.py [CSV] [--out PNG]
"""
import argparse
import csv
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("plot_ppe_scaling.py: needs matplotlib (apt-get install python3-matplotlib)")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("csv", nargs="?", default="bench/ppe_scaling.csv")
    ap.add_argument("--out", default="bench/ppe_scaling.png")
    a = ap.parse_args()
    series = {}
    with open(a.csv) as f:
        for row in csv.DictReader(line for line in f if not line.startswith("#")):
            s = series.setdefault(row["solver"], ([], [], []))
            s[0].append(int(row["n"]))
            s[1].append(float(row["seconds"]))
            s[2].append(float(row["iterations"]) if row["iterations"] else None)
    fig, (ax_t, ax_i) = plt.subplots(1, 2, figsize=(10, 4))
    for k, (name, (n, sec, its)) in enumerate(sorted(series.items())):
        colour = "C%d" % k  # the same colour for a series in both panels
        ax_t.loglog(n, sec, "o-", color=colour, label=name)
        if all(i is not None for i in its):
            ax_i.loglog(n, its, "o-", color=colour, label=name)
    n_ref = [2500, 250000]
    ax_t.loglog(n_ref, [1e-3, 1e-1], "k:", label="slope 1")
    ax_t.set_xlabel("N"), ax_t.set_ylabel("seconds per solve"), ax_t.grid(True, which="both", alpha=0.3)
    ax_i.set_xlabel("N"), ax_i.set_ylabel("iterations"), ax_i.grid(True, which="both", alpha=0.3)
    ax_t.legend(fontsize=8), ax_i.legend(fontsize=8)
    fig.suptitle("ISPH Poisson solve against N (2 threads)")
    fig.tight_layout()
    fig.savefig(a.out, dpi=100)
    print("wrote", a.out)


if __name__ == "__main__":
    main()
