"""Hall figures (cf. Figs. 9-11): example AMR drives and a UAV flight with their anchors and
initializations, and the AMR Monte Carlo per anchor. The examples' paths come from the simulated
files in build/examples/ (scripts/halls.sh), the estimates from results/examples/."""
import numpy as np

from common import COLORS, GATED, RESULTS, number, plt, read_csv, save

BUILD = RESULTS.parent / "build" / "examples"


def top_view(ax, name, title):
    poses = [p for p in read_csv(BUILD / name / "poses.csv") if p["tag_id"] == "0"]
    anchors = read_csv(BUILD / name / "anchors.csv")
    estimates = read_csv(RESULTS / "examples" / name / "estimates.csv")
    ax.plot([number(p["x"]) for p in poses], [number(p["y"]) for p in poses], lw=0.5, color="#999999")
    gated = {e["anchor_id"]: e for e in estimates if e["method"] == GATED}
    for a in anchors:
        done = gated[a["anchor_id"]]["initialized"] == "1"
        ax.scatter(number(a["x"]), number(a["y"]), marker="^", s=36, color=COLORS[GATED] if done else "#cccccc",
                   edgecolor="k", zorder=3)
        ax.annotate(a["anchor_id"], (number(a["x"]), number(a["y"])), textcoords="offset points", xytext=(0, -10),
                    ha="center", fontsize=6)
    count = sum(e["initialized"] == "1" for e in gated.values())
    errors = [number(e["err_m"]) for e in gated.values() if e["initialized"] == "1"]
    detail = f", mean error {np.mean(errors):.2f} m" if errors else ""
    ax.set_title(f"{title}\n{count}/{len(anchors)} initialized{detail}")
    ax.set_xlabel("x (m)")
    ax.set_aspect("equal")


fig, axes = plt.subplots(1, 3, figsize=(7.0, 2.2))
for ax, (name, title) in zip(axes, [("amr_covering", "covering"), ("amr_partial", "partial"),
                                    ("amr_straight", "straight")]):
    top_view(ax, name, title)
axes[0].set_ylabel("y (m)")
fig.suptitle("AMR in front of a hall, two tags (cf. Fig. 9): green anchors initialized at PDOP < 1")
save(fig, RESULTS / "examples" / "amr_examples.png")

fig, axes = plt.subplots(1, 2, gridspec_kw={"width_ratios": [1, 2.2]})
top_view(axes[0], "uav", "UAV")
axes[0].set_ylabel("y (m)")
trace = read_csv(BUILD / "uav" / "trace.csv")
estimates = {e["anchor_id"]: e for e in read_csv(RESULTS / "examples" / "uav" / "estimates.csv") if e["method"] == GATED}
for anchor, color in zip(sorted(estimates, key=int), plt.cm.tab10.colors):
    rows = [r for r in trace if r["anchor_id"] == anchor and r["pdop"] != "inf"]
    axes[1].plot([number(r["t"]) for r in rows], [number(r["pdop"]) for r in rows], color=color, lw=0.8,
                 label=f"anchor {anchor}")
    if estimates[anchor]["initialized"] == "1":
        axes[1].axvline(number(estimates[anchor]["t_init"]), color=color, ls="--", lw=0.8)
axes[1].axhline(1.0, color="k", lw=0.6, ls=":")
axes[1].set_yscale("log")
axes[1].set_ylim(0.3, 100)
axes[1].set_xlabel("time (s)")
axes[1].set_ylabel("closest-point PDOP")
axes[1].legend(ncol=2)
axes[1].set_title("PDOP per anchor; dashed: initialization (cf. Fig. 10)")
save(fig, RESULTS / "examples" / "uav_example.png")

attempts = read_csv(RESULTS / "amr_hall" / "attempts.csv")
anchor_ids = sorted({int(a["anchor_id"]) for a in attempts})
rows = list(dict.fromkeys(a["row"] for a in attempts))
fig, axes = plt.subplots(1, 2)
width = 0.8 / len(rows)
for i, (row, color) in enumerate(zip(rows, ["#1b9e77", "#7570b3", "#d95f02"])):
    chosen = [a for a in attempts if a["row"] == row and a["method"] == GATED]
    rate = [100 * np.mean([a["initialized"] == "1" for a in chosen if int(a["anchor_id"]) == k]) for k in anchor_ids]
    err = [np.mean([number(a["err_m"]) for a in chosen if int(a["anchor_id"]) == k and a["initialized"] == "1"] or [np.nan])
           for k in anchor_ids]
    x = np.array(anchor_ids) + (i - (len(rows) - 1) / 2) * width
    axes[0].bar(x, rate, width, color=color, label=row)
    axes[1].bar(x, err, width, color=color, label=row)
axes[0].set_ylabel("gated: initialized (% of runs)")
axes[1].set_ylabel("gated: mean error (m)")
for ax in axes:
    ax.set_xlabel("anchor (along the hall front)")
    ax.set_xticks(anchor_ids)
axes[0].legend()
fig.suptitle("AMR Monte Carlo, 100 runs per trajectory type: which anchors initialize at PDOP < 1")
save(fig, RESULTS / "amr_hall" / "per_anchor.png")
