"""Initialization error against the Cramer-Rao bound of each attempt's data (Table I attempts)."""
import numpy as np

from common import COLORS, FIXED, GATED, RESULTS, number, plt, read_csv, save

attempts = [a for a in read_csv(RESULTS / "table1" / "attempts.csv") if a["initialized"] == "1" and a["crlb_m"]]
fig, axes = plt.subplots(1, 2, sharey=True)
for ax, method in zip(axes, [FIXED, GATED]):
    chosen = [a for a in attempts if a["method"] == method]
    crlb = np.array([number(a["crlb_m"]) for a in chosen])
    error = np.array([number(a["err_m"]) for a in chosen])
    ax.scatter(crlb, error, s=2, alpha=0.3, color=COLORS[method], rasterized=True)
    line = np.array([1e-3, 1e3])
    ax.plot(line, line, "k-", lw=0.8, label="error = CRLB")
    ax.plot(line, 3 * line, "k--", lw=0.8, label="3 x CRLB")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(crlb[crlb > 0].min() / 2, crlb.max() * 2)
    ax.set_ylim(1e-3, max(error.max() * 2, 1))
    ax.set_xlabel("CRLB on the position error (m)")
    within = np.mean(error <= 3 * crlb) * 100
    ax.set_title(f"{'gated (ours)' if method == GATED else 'fixed window'}: {len(chosen)} inits, "
                 f"{within:.0f}% within 3 x CRLB")
axes[0].set_ylabel("initialization error (m)")
axes[0].legend(loc="upper left")
save(fig, RESULTS / "table1" / "error_vs_crlb.png")
