"""The bias-aware view: at each gated initialization of Table I, the true PDOP the paper's trigger
approximates against the true bias-aware DOP (the position block with the bias estimated)."""
import numpy as np

from common import GATED, RESULTS, number, plt, read_csv, save

attempts = [a for a in read_csv(RESULTS / "table1" / "attempts.csv")
            if a["method"] == GATED and a["initialized"] == "1"]
pdop_true = np.array([number(a["pdop_true"]) for a in attempts])
bias_aware = np.array([number(a["bias_aware_dop"]) for a in attempts])
fig, axes = plt.subplots(1, 2)
axes[0].scatter(pdop_true, bias_aware, s=3, alpha=0.4, color="#7570b3", rasterized=True)
line = np.array([0.05, 20])
axes[0].plot(line, line, "k-", lw=0.8)
axes[0].axhline(1.0, color="k", lw=0.6, ls=":")
axes[0].set_xscale("log")
axes[0].set_yscale("log")
axes[0].set_xlabel("true PDOP (3 columns, Eq. (3))")
axes[0].set_ylabel("true bias-aware DOP (4 columns)")
above = 100 * np.mean(bias_aware > 1)
axes[0].set_title(f"{len(attempts)} gated inits: bias-aware DOP > 1 in {above:.0f}%")
ratio = bias_aware / pdop_true
axes[1].hist(ratio[np.isfinite(ratio)], bins=np.linspace(1, 3, 41), color="#7570b3", alpha=0.7)
axes[1].set_xlabel("bias-aware DOP / true PDOP")
axes[1].set_ylabel("gated initializations")
axes[1].set_title(f"median bias-aware / true PDOP: {np.nanmedian(ratio):.2f}")
fig.suptitle("Table I: what the trigger sees (PDOP) vs what bounds the error (bias-aware DOP)")
save(fig, RESULTS / "table1" / "bias_aware.png")
