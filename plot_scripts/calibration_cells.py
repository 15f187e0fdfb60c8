"""Table I cell by cell, before and after calibration: ours / paper on a log axis (mean and range
over the verification seeds), with the +-25% band. Reads results/calibrate_table1/verification.csv."""
import numpy as np

from common import COLORS, RESULTS, number, plt, read_csv, save

FOLDER = RESULTS / "calibrate_table1"
rows = [r for r in read_csv(FOLDER / "verification.csv") if r["scored"] == "1"]
short = {"fixed_window": "fixed", "pdop_closest_point": "gated"}
cells = list(dict.fromkeys((r["row"], r["method"], r["column"]) for r in rows))
fig, ax = plt.subplots(figsize=(7.0, 3.0))
x = np.arange(len(cells))
for offset, config, color in ((-0.18, "before", COLORS["fixed_window"]), (0.18, "after", COLORS["pdop_closest_point"])):
    ratios = []
    for cell in cells:
        values = [number(r["ours"]) / number(r["paper"]) for r in rows
                  if (r["row"], r["method"], r["column"]) == cell and r["config"] == config and r["ours"] != ""]
        ratios.append(values or [float("nan")])
    floor = 0.01  # a zero (no initialization worse than 1 m) is drawn on the axis floor
    mean = np.maximum(np.array([np.mean(v) for v in ratios]), floor)
    low = mean - np.maximum(np.array([np.min(v) for v in ratios]), floor)
    high = np.maximum(np.array([np.max(v) for v in ratios]), floor) - mean
    ax.errorbar(x + offset, mean, yerr=np.vstack([low, high]), fmt="o", ms=3, capsize=2, color=color,
                label="as configured" if config == "before" else "calibrated")
ax.axhspan(0.75, 1.25, color=COLORS["paper"], alpha=0.15, label="within +-25% of the paper")
ax.axhline(1.0, color=COLORS["paper"], lw=0.8)
ax.set_yscale("log")
ax.set_ylim(0.008, 5)
ax.set_xticks(x, [f"{row} {short.get(method, method)} {column}" for row, method, column in cells], rotation=90)
ax.set_ylabel("ours / paper")
ax.legend(loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=3, frameon=False)
ax.set_title("Table I cells at full size on the verification seeds (mean and range; 0 drawn at 0.01)", pad=18)
save(fig, FOLDER / "cells.png")
