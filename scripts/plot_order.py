#!/usr/bin/env python3
"""Plot of `arksph study order`: error against dt (log-log) per table, with the nominal slopes.

usage: plot_order.py order_errors.csv order_fit.csv order.png [Y-AXIS LABEL]
One panel for the whole state's error; when the study measured them (a fine-step reference), two
more for the velocity and the pressure errors. Exits 0 without a plot (message on stderr) when
matplotlib is missing.
"""
import csv
import sys

PANELS = [("error", "observed_order", None),
          ("velocity_error", "velocity_order", "max-norm velocity error"),
          ("pressure_error", "pressure_order", "max-norm pressure error")]


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
    with open(sys.argv[1]) as f:
        rows = list(csv.DictReader(f))
    fits = {}
    with open(sys.argv[2]) as f:
        for row in csv.DictReader(f):
            fits[row["table"]] = row
    panels = [p for p in PANELS if p[0] == "error" or any(float(r.get(p[0]) or 0) > 0 for r in rows)]
    if len(panels) == 2:  # a velocity panel without a pressure one repeats the analytic error
        panels = panels[:1]
    fig, axes = plt.subplots(1, len(panels), figsize=(7 * len(panels), 5), squeeze=False)
    for ax, (column, fit_column, ylabel) in zip(axes[0], panels):
        errors = {}
        for row in rows:
            errors.setdefault(row["table"], []).append((float(row["dt"]), float(row[column])))
        for table, pts in errors.items():
            pts.sort()
            dt = [p[0] for p in pts]
            err = [p[1] for p in pts]
            fit = fits.get(table, {})
            nominal = int(fit.get("nominal_order", 0))
            label = "%s: %s (nominal %d)%s" % (table.replace("ARKODE_", "").replace("ARKSPH_", ""),
                                               fit.get(fit_column, "?")[:5], nominal,
                                               "  FLAG" if column == "error" and fit.get("flag") == "FLAG" else "")
            line, = ax.loglog(dt, err, "o-", label=label)
            # the nominal slope through the largest step's error
            ax.loglog(dt, [err[-1] * (d / dt[-1]) ** nominal for d in dt], ":", color=line.get_color())
        ax.set_xlabel("dt")
        default = sys.argv[4] if len(sys.argv) > 4 else "max-norm state error against the reference run"
        ax.set_ylabel(ylabel or default)
        ax.set_title("observed order (dotted: nominal slope)")
        ax.legend(fontsize=7)
        ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(sys.argv[3], dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
