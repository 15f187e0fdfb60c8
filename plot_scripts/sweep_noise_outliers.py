"""Noise x outlier-rate grid as heatmaps."""
import numpy as np

from common import FIXED, GATED, RESULTS, number, plt, read_csv, save

rows = read_csv(RESULTS / "sweep_noise_outliers" / "sweep.csv")
key = "scenario.ranging.outlier_probability"
sigmas = list(dict.fromkeys(r["row"] for r in rows))
rates = list(dict.fromkeys(r[key] for r in rows))


def grid(method, value):
    return np.array([[value(next(r for r in rows if r["row"] == s and r[key] == p and r["method"] == method))
                      for p in rates] for s in sigmas])


attempts = number(rows[0]["init"])  # fixed window: every attempt
panels = [("fixed window: average error (m)", grid(FIXED, lambda r: number(r["avg_m"])), "{:.2f}"),
          ("gated: average error (m)", grid(GATED, lambda r: number(r["avg_m"])), "{:.2f}"),
          ("gated: initialized (%)", grid(GATED, lambda r: 100 * number(r["init"]) / attempts), "{:.0f}")]
fig, axes = plt.subplots(1, 3)
for ax, (title, values, fmt) in zip(axes, panels):
    image = ax.imshow(values, origin="lower", aspect="auto", cmap="magma_r")
    for i in range(len(sigmas)):
        for j in range(len(rates)):
            ax.text(j, i, fmt.format(values[i, j]), ha="center", va="center", fontsize=6,
                    color="white" if values[i, j] > np.nanmean(values) else "black")
    ax.set_xticks(range(len(rates)), [f"{100 * float(p):.0f}" for p in rates])
    ax.set_yticks(range(len(sigmas)), sigmas)
    ax.set_xlabel("outlier rate (%)")
    ax.set_title(title)
    ax.grid(False)
axes[0].set_ylabel("sigma_d (m)")
fig.suptitle("Noise x outlier rate (isolated positive spikes of 1-10 m; tau = 2 sigma_d, c = sigma_d)")
save(fig, RESULTS / "sweep_noise_outliers" / "noise_outliers.png")
