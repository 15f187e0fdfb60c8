"""The navigation studies' position error over time (docs/navigation.md), and the closed-loop
exploration studies' (docs/guidance.md, a policy for each method): the mean over realizations of
each method's error, per time bin, from each study's navigation_error.csv."""
from common import COLORS, FIXED, GATED, RESULTS, number, plt, read_csv, save

STYLE = {FIXED: COLORS[FIXED], GATED: COLORS[GATED], "dop4_closest_point": "#1f78b4", "dop4_confidence": "#a6cee3",
         "certified": "#7570b3", "pdop_ls": "#e7298a", "pdop_nls": "#e6ab02", "true_anchors": "#000000",
         "no_anchors": "#999999", "pattern": "#999999", "guided": "#7570b3", "oracle": "#000000",
         "dop_waypoints": "#e6ab02"}
STUDIES = [  # folder, rows shown, title
    ("navigation_tunnel", ["1", "4"], "Table I's tunnel, wheel odometry"),
    ("navigation_uav_hall", ["base"], "UAV hall, VIO (cf. Table IV)"),
    ("navigation_radio_biases", ["eq1", "all"], "UAV hall, VIO, radio biases"),
    ("exploration_uav_hall", ["flat_pattern", "sweeping_pattern"], "Closed loop, UAV hall, VIO"),
    ("exploration_tunnel", ["flat_floor", "rough_ground"], "Closed loop, tunnel, wheel odometry"),
]

for folder, rows, title in STUDIES:
    lines = read_csv(RESULTS / folder / "navigation_error.csv")
    fig, axes = plt.subplots(1, len(rows), sharey=True, squeeze=False)
    for ax, row in zip(axes[0], rows):
        methods = list(dict.fromkeys(line["method"] for line in lines if line["row"] == row))
        for method in methods:
            series = [line for line in lines if line["row"] == row and line["method"] == method]
            baseline = method in ("true_anchors", "no_anchors", "pattern")
            ax.plot([number(s["t_s"]) for s in series], [number(s["error_mean_m"]) for s in series],
                    color=STYLE.get(method), lw=1.4 if method == GATED else 0.9, ls="--" if baseline else "-",
                    label=method)
        ax.set_yscale("log")
        ax.set_xlabel("time (s)")
        ax.set_title(f"{title}: row {row}")
    axes[0][0].set_ylabel("mean position error (m)")
    axes[0][-1].legend(loc="upper left", bbox_to_anchor=(1.02, 1.0))
    save(fig, RESULTS / folder / "navigation_error.png")
