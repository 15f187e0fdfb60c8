"""Fig. 6 analog: closest-point and true PDOP (and the bias-aware DOP) against the sample index,
and the NLS initialization error at each checkpoint; median and 25-75% band over the runs."""
import numpy as np

from common import COLORS, GATED, RESULTS, number, plt, read_csv, save

trace = read_csv(RESULTS / "pdop_study" / "pdop_trace.csv")
by_n = {}
for row in trace:
    by_n.setdefault(int(row["n"]), []).append(row)
runs = len({r["realization"] for r in trace})
# Only sample counts that at least half of the runs reach: beyond, a few long runs make the curves.
n = np.array(sorted(k for k in by_n if len(by_n[k]) >= runs / 2))


def band(column):
    values = [np.array([number(r[column]) for r in by_n[k]]) for k in n]
    return np.array([np.nanpercentile(v, [25, 50, 75]) if np.isfinite(v).any() else [np.nan] * 3 for v in values]).T


fig, axes = plt.subplots(1, 2)
for column, label, color in [("pdop_closest_point", "closest-point PDOP (ours)", COLORS[GATED]),
                             ("pdop_true", "true PDOP", "k"),
                             ("bias_aware_dop", "true bias-aware DOP", "#7570b3")]:
    low, median, high = band(column)
    axes[0].plot(n, median, color=color, label=label)
    axes[0].fill_between(n, low, high, color=color, alpha=0.2)
axes[0].axhline(1.0, color="k", lw=0.6, ls=":")
axes[0].set_yscale("log")
axes[0].set_ylim(0.05, 100)
axes[0].set_xlabel("accepted samples")
axes[0].set_ylabel("PDOP (median, 25-75%)")
axes[0].legend()
low, median, high = band("nls_err_m")
axes[1].plot(n, median, color=COLORS[GATED], label="LS + NLS on the samples so far")
axes[1].fill_between(n, low, high, color=COLORS[GATED], alpha=0.2)
axes[1].set_yscale("log")
axes[1].set_xlabel("accepted samples")
axes[1].set_ylabel("initialization error (m)")
axes[1].legend()
fig.suptitle(f"One wall anchor, {runs} random runs, sigma_d = 0.15 m (cf. Fig. 6)")
save(fig, RESULTS / "pdop_study" / "pdop_fig6.png")
