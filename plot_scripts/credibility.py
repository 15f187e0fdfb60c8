"""Covariances a navigation filter can trust? The NEES of each initialized attempt's position
against the chi-square distribution of 3 degrees of freedom it follows when the covariance is
credible: left, the Table I attempts (empirical CDF per method, rows pooled); right, the ANEES of
every solver x trigger of the stress test (row 1, consistency filter) with the 95% band of a
credible estimator."""
import math

import numpy as np

from common import RESULTS, number, plt, read_csv, save

CHI2_3_95 = 7.814727903251178


def chi2_3_cdf(x):
    return math.erf(math.sqrt(x / 2)) - math.sqrt(2 * x / math.pi) * math.exp(-x / 2)


fig, axes = plt.subplots(1, 2, figsize=(11, 4.8))
attempts = read_csv(RESULTS / "table1" / "attempts.csv")
grid = np.logspace(-2, 4, 200)
axes[0].plot(grid, [chi2_3_cdf(x) for x in grid], "k-", lw=1.5, label="chi-square, 3 dof (credible)")
for method, color in (("fixed_window", "#d95f02"), ("pdop_closest_point", "#7570b3")):
    nees = np.sort([number(a["nees_pos"]) for a in attempts
                    if a["method"] == method and a["initialized"] == "1" and a["nees_pos"]])
    above = 100 * np.mean(nees > CHI2_3_95)
    axes[0].step(nees, np.arange(1, len(nees) + 1) / len(nees), where="post", color=color,
                 label=f"{method}: ANEES {nees.mean():.1f}, {above:.0f}% > 7.81")
axes[0].axvline(CHI2_3_95, color="k", lw=0.6, ls=":")
axes[0].set_xscale("log")
axes[0].set_xlabel("position NEES of an initialization")
axes[0].set_ylabel("fraction of initializations")
axes[0].set_title("Table I, all rows")
axes[0].legend(fontsize=7, loc="upper left", bbox_to_anchor=(0.0, -0.2))

cells = {}
for name in ("stress", "stress_ransac"):
    for r in read_csv(RESULTS / name / "sweep.csv"):
        if r["row"] == "1" and r["anees_pos"]:
            cells[(r["estimator.solver"], r["estimator.filter.kind"], r["method"])] = r
solvers = sorted({(s, f) for s, f, _ in cells if f in ("consistency", "ransac")})
triggers = ["pdop_closest_point", "fixed_window", "pdop_true"]
width = 0.8 / len(triggers)
for i, (trigger, color) in enumerate(zip(triggers, ("#7570b3", "#d95f02", "#1b9e77"))):
    for j, key in enumerate(solvers):
        r = cells.get((key[0], key[1], trigger))
        if r is None:
            continue
        x = j + (i - 1) * width
        axes[1].bar(x, number(r["anees_pos"]), width, color=color, label=trigger if j == 0 else None)
        axes[1].plot([x - width / 2, x + width / 2], [number(r["anees_hi"])] * 2, "k-", lw=0.8)
axes[1].axhline(3.0, color="k", lw=0.6, ls=":")
axes[1].set_yscale("log")
axes[1].set_xticks(range(len(solvers)))
axes[1].set_xticklabels([f"{s}\n{f}" for s, f in solvers], rotation=60, fontsize=6)
axes[1].set_ylabel("ANEES of the position (credible: 3)")
axes[1].set_title("stress row 1 (black tick: credible bound)")
axes[1].legend(fontsize=7, loc="upper left", bbox_to_anchor=(0.0, -0.45), ncol=3)
fig.suptitle("Credibility of the reported covariances")
save(fig, RESULTS / "stress" / "credibility.png")
