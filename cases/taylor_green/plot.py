"""taylor_green.png from results.csv: relative L1 velocity error at t = 1 against resolution, per
scheme, with (solid) and without (dashed) regularisation, Re = 100 and 1000."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
fig, axes = plt.subplots(1, 2, figsize=(9, 3.6), sharey=True)
colours = {"isph": "C0", "isph-gpps": "C1", "wcsph": "C2"}
for ax, re in zip(axes, ["100", "1000"]):
    for scheme, colour in colours.items():
        for reg, style in (("default", "-o"), ("none", "--x")):
            pts = sorted((int(r["n"]), float(r["l1_t1"])) for r in rows
                         if r["scheme"] == scheme and r["regularisation"] == reg and r["re"] == re)
            if pts:
                label = scheme + (" (defaults)" if reg == "default" else " (no regularisation)")
                ax.loglog([p[0] for p in pts], [p[1] for p in pts], style, color=colour, label=label)
    ax.set_title("Taylor-Green, Re = " + re + ", t = 1")
    ax.set_xlabel("particles per side")
    ax.grid(True, which="both", alpha=0.3)
axes[0].set_ylabel("relative L1 velocity error")
axes[1].legend(fontsize=7)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=90)
