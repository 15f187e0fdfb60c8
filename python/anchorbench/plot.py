"""Figures of a replay (docs/python.md): the anchors against the truth, and the error against time.

    import anchorbench as ab, anchorbench.plot
    replayed = ab.replay(poses, ranges, anchors=anchors)
    ab.plot.anchors(replayed)                 # the plan view: estimates, their 99% radius, the truth
    ab.plot.errors_over_time(replayed)        # each trigger: when each anchor came, how far off

Each takes a replay's Result (or its estimates DataFrame) and an optional matplotlib Axes, and
returns the Axes. matplotlib (Debian's python3-matplotlib) is imported only here.
"""

from __future__ import annotations

from typing import Optional


def _estimates(result):
    return result if hasattr(result, "columns") else result.estimates


def _surveyed(truth):
    """anchors.csv as a DataFrame, indexed by anchor id (None: no truth to draw)."""
    return None if truth is None else truth.set_index("anchor_id")[["x", "y", "z"]]


def anchors(result, truth=None, ax=None, triggers: Optional[list] = None):
    """Plan view (x, y) of each trigger's initialized anchors, each with a circle of its 99% radius
    (`radius99_m`: the largest axis of its 99% region, so the circle holds the region's shadow),
    and the surveyed anchors as crosses when `truth` (anchors.csv as a DataFrame) is given."""
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle

    e = _estimates(result)
    ax = ax or plt.subplots(figsize=(6, 5))[1]
    done = e[e["initialized"] == 1]
    methods = triggers or list(dict.fromkeys(done["method"]))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for k, method in enumerate(methods):
        rows = done[done["method"] == method]
        colour = colours[k % len(colours)]
        ax.scatter(rows["x"], rows["y"], s=18, color=colour, label=f"{method} ({len(rows)})", zorder=3)
        if "radius99_m" in rows:
            for x, y, r in zip(rows["x"], rows["y"], rows["radius99_m"]):
                if r == r:  # not NaN
                    ax.add_patch(Circle((x, y), r, fill=False, color=colour, alpha=0.5, lw=0.8))
    surveyed = _surveyed(truth)
    if surveyed is not None:
        ax.scatter(surveyed["x"], surveyed["y"], marker="x", s=40, color="black", label="surveyed", zorder=4)
        for anchor_id, row in surveyed.iterrows():
            ax.annotate(str(anchor_id), (row["x"], row["y"]), textcoords="offset points", xytext=(4, 4), fontsize=7)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.legend(fontsize=7)
    return ax


def errors_over_time(result, ax=None, triggers: Optional[list] = None):
    """For each trigger, each initialized anchor's error (needs the truth: `err_m`) at its `t_init`
    (points, left axis), and the trigger's count of anchors initialized so far (steps, right axis)."""
    import matplotlib.pyplot as plt

    e = _estimates(result)
    if "err_m" not in e or e["err_m"].isna().all():
        raise ValueError("errors_over_time: the replay knew no truth (give anchors= to ab.replay)")
    ax = ax or plt.subplots(figsize=(6, 4))[1]
    done = e[(e["initialized"] == 1) & e["err_m"].notna()]
    methods = triggers or list(dict.fromkeys(e["method"]))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    count_axis = ax.twinx()
    for k, method in enumerate(methods):
        rows = done[done["method"] == method].sort_values("t_init")
        colour = colours[k % len(colours)]
        ax.scatter(rows["t_init"], rows["err_m"], s=16, color=colour, label=method)
        count_axis.step(list(rows["t_init"]), range(1, len(rows) + 1), where="post", color=colour, alpha=0.4)
    ax.set_xlabel("time of initialization (the log's unit)")
    ax.set_ylabel("error (m), points")
    count_axis.set_ylabel("anchors initialized, steps")
    ax.legend(fontsize=7)
    return ax
