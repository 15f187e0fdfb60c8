"""tau sweep: the consistency check's threshold against the range noise of each Table I row."""
import numpy as np

from common import FIXED, GATED, RESULTS, number, plt, read_csv, save

rows = read_csv(RESULTS / "sweep_tau" / "sweep.csv")
key = "estimator.filter.tau_m"
sigma = {"1": 0.1, "2": 0.125, "3": 0.15, "4": 0.5}  # configs/table1.yaml
fig, axes = plt.subplots(1, 2)
for name, color in zip(sigma, plt.cm.viridis(np.linspace(0, 0.9, len(sigma)))):
    gated = [r for r in rows if r["row"] == name and r["method"] == GATED]
    fixed = [r for r in rows if r["row"] == name and r["method"] == FIXED]
    tau = np.array([number(r[key]) for r in gated])
    attempts = number(fixed[0]["init"])
    label = f"row {name} (sigma_d = {sigma[name]} m)"
    axes[0].plot(tau, [100 * number(r["init"]) / attempts for r in gated], "-o", ms=3, color=color, label=label)
    axes[1].plot(tau, [number(r["avg_m"]) for r in fixed], "--s", ms=3, color=color)
    axes[1].plot(tau, [number(r["avg_m"]) for r in gated], "-o", ms=3, color=color, label=label)
    for ax in axes:
        ax.axvline(2 * sigma[name], color=color, lw=0.8, ls=":")
axes[0].set_ylabel("gated: initialized anchors (%)")
axes[1].set_ylabel("average error (m)")
axes[1].set_title("solid: gated, dashed: fixed window")
axes[1].set_yscale("log")
for ax in axes:
    ax.set_xlabel("tau (m); dotted: 2 sigma_d")
axes[0].legend()
fig.suptitle("Consistency-check threshold tau against the range noise")
save(fig, RESULTS / "sweep_tau" / "tau.png")
