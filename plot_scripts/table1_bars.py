"""Table I as bars: Avg error, bad-init Ratio and Init, ours (with 95% intervals) beside the paper."""
import numpy as np

from common import COLORS, FIXED, GATED, RESULTS, number, plt, read_csv, save

rows = read_csv(RESULTS / "table1" / "summary.csv")
names = list(dict.fromkeys(r["row"] for r in rows))
x = np.arange(len(names))
width = 0.2
fig, axes = plt.subplots(1, 3)
panels = [("avg_m", "avg_lo", "avg_hi", "paper_avg_m", "average error (m)"),
          ("ratio_pct", "ratio_lo", "ratio_hi", "paper_ratio_pct", "initializations > 1 m (%)"),
          ("init", None, None, "paper_init", "initialized anchors (of 3000)")]
for ax, (key, lo, hi, paper_key, label) in zip(axes, panels):
    for i, method in enumerate([FIXED, GATED]):
        cells = [next(r for r in rows if r["row"] == n and r["method"] == method) for n in names]
        ours = np.array([number(c[key]) for c in cells])
        paper = np.array([number(c.get(paper_key, "")) for c in cells])
        offset = (2 * i - 1.5) * width
        errors = None
        if lo:
            low = np.array([number(c[lo]) for c in cells])
            high = np.array([number(c[hi]) for c in cells])
            errors = np.vstack([ours - low, high - ours])
        ax.bar(x + offset, ours, width, yerr=errors, capsize=2, color=COLORS[method],
               label=f"{'gated (ours)' if method == GATED else 'fixed window'}")
        ax.bar(x + offset + width, paper, width, color=COLORS[method], alpha=0.35, hatch="//",
               label=f"{method}, paper")
    ax.set_xticks(x + width / 2, [f"row {n}" for n in names])
    ax.set_ylabel(label)
axes[0].legend(loc="upper left")
fig.suptitle("Table I: PDOP-gated vs fixed window (solid: ours with 95% intervals, bootstrap for Avg, Wilson for "
             "Ratio; hatched: paper)")
save(fig, RESULTS / "table1" / "table1_bars.png")
