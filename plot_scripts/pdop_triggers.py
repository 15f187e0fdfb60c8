"""Figs. 7/8 analog: each PDOP estimate minus the true PDOP in 10 s bins (box plots), per method."""
import numpy as np

from common import RESULTS, number, plt, read_csv, save

trace = read_csv(RESULTS / "pdop_study" / "pdop_trace.csv")
methods = [("pdop_closest_point", "closest point (ours)", "#1b9e77"), ("pdop_ls", "at the LS estimate", "#d95f02"),
           ("pdop_nls", "at the NLS estimate", "#e6ab02")]
bins = np.arange(0, 120, 10)
fig, axes = plt.subplots(1, 3, sharey=True)
for ax, (column, label, color) in zip(axes, methods):
    data = []
    for start in bins:
        rows = [r for r in trace if start <= number(r["t"]) < start + 10]
        diff = np.array([number(r[column]) - number(r["pdop_true"]) for r in rows])
        data.append(diff[np.isfinite(diff)])
    ax.boxplot(data, positions=bins + 5, widths=6, showfliers=False, patch_artist=True,
               boxprops={"facecolor": color, "alpha": 0.6}, medianprops={"color": "k"})
    over = [100 * np.mean(d < 0) if len(d) else np.nan for d in data]
    ax.set_title(f"{label}\nbelow the true PDOP: {np.nanmean(over):.0f}%")
    ax.axhline(0, color="k", lw=0.6)
    ax.set_yscale("symlog", linthresh=0.1)
    ax.set_xticks(bins[::2] + 5, [f"{b}" for b in bins[::2]])
    ax.set_xlabel("time since first range (s)")
axes[0].set_ylabel("PDOP estimate - true PDOP")
fig.suptitle("PDOP estimates against the truth (cf. Fig. 7; boxes 25-75%, whiskers 1.5 IQR)")
save(fig, RESULTS / "pdop_study" / "pdop_triggers.png")
