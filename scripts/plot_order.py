#!/usr/bin/env python3
"""Plot of `arksph study order`: error against dt (log-log) per table, with the nominal slopes.

usage: plot_order.py order_errors.csv order_fit.csv order.png [Y-AXIS LABEL]
Exits 0 without a plot (message on stderr) when matplotlib is missing.
"""
import csv
import sys


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("plot_order.py: matplotlib not available, no plot", file=sys.stderr)
        return 0
    errors, fits = {}, {}
    with open(sys.argv[1]) as f:
        for row in csv.DictReader(f):
            errors.setdefault(row["table"], []).append((float(row["dt"]), float(row["error"])))
    with open(sys.argv[2]) as f:
        for row in csv.DictReader(f):
            fits[row["table"]] = row
    fig, ax = plt.subplots(figsize=(7, 5))
    for i, (table, pts) in enumerate(errors.items()):
        pts.sort()
        dt = [p[0] for p in pts]
        err = [p[1] for p in pts]
        fit = fits.get(table, {})
        nominal = int(fit.get("nominal_order", 0))
        label = "%s: %s (nominal %d)%s" % (table.replace("ARKODE_", "").replace("ARKSPH_", ""),
                                           fit.get("observed_order", "?")[:5], nominal,
                                           "  FLAG" if fit.get("flag") == "FLAG" else "")
        line, = ax.loglog(dt, err, "o-", label=label)
        # the nominal slope through the largest step's error
        ax.loglog(dt, [err[-1] * (d / dt[-1]) ** nominal for d in dt], ":", color=line.get_color())
    ax.set_xlabel("dt")
    ax.set_ylabel(sys.argv[4] if len(sys.argv) > 4 else "max-norm state error against the reference run")
    ax.set_title("observed order (dotted: nominal slope)")
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(sys.argv[3], dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main())
