"""PDOP threshold sweep: how many anchors initialize, and how many of those badly."""
import numpy as np

from common import COLORS, FIXED, GATED, RESULTS, number, plt, read_csv, save

rows = read_csv(RESULTS / "sweep_pdop_threshold" / "sweep.csv")
key = "estimator.trigger.pdop_threshold"
fig, axes = plt.subplots(1, 3)
for name, style in [("1", "-o"), ("4", "--s")]:
    gated = [r for r in rows if r["row"] == name and r["method"] == GATED]
    fixed = [r for r in rows if r["row"] == name and r["method"] == FIXED]
    threshold = np.array([number(r[key]) for r in gated])
    attempts = number(fixed[0]["init"])  # the fixed window initializes every attempt
    label = f"row {name}"
    axes[0].plot(threshold, [100 * number(r["init"]) / attempts for r in gated], style, ms=3,
                 color=COLORS[GATED], label=label)
    axes[1].plot(threshold, [number(r["ratio_pct"]) for r in gated], style, ms=3, color=COLORS[GATED], label=label)
    axes[1].axhline(number(fixed[0]["ratio_pct"]), ls=style[:-1], color=COLORS[FIXED], lw=1,
                    label=f"fixed window, row {name}")
    axes[2].plot(threshold, [number(r["med_m"]) for r in gated], style, ms=3, color=COLORS[GATED], label=label)
for ax in axes:
    ax.axvline(1.0, color="k", lw=0.6, ls=":")
    ax.set_xlabel("PDOP threshold")
axes[0].set_ylabel("gated: initialized anchors (%)")
axes[1].set_ylabel("initializations > 1 m (%)")
axes[2].set_ylabel("gated: median error (m)")
axes[2].set_yscale("log")
axes[0].legend()
axes[1].legend()
fig.suptitle("PDOP threshold sweep (Table I rows 1: sigma_d = 0.1 m, 4: sigma_d = 0.5 m; dotted: the paper's 1)")
save(fig, RESULTS / "sweep_pdop_threshold" / "pdop_threshold.png")
