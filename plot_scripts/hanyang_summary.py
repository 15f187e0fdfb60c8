"""Per-anchor outcomes of the Hanyang replays (results/hanyang/*/estimates.csv) as one Markdown
table, plus a figure of one LOS and one NLOS case: trajectory, anchors and estimates."""
import pathlib

from common import COLORS, FIXED, GATED, RESULTS, latency_text, number, plt, read_csv, save

root = RESULTS / "hanyang"
cases = sorted(p for p in root.iterdir() if (p / "estimates.csv").exists())
lines = ["# Hanyang outdoor UWB dataset: PDOP-gated vs fixed window", "",
         "Replayed with `configs/hanyang.yaml` (PDOP threshold 1, tau 0.2 m, c 0.1 m) by "
         "`scripts/hanyang.sh`. Per anchor: gated outcome (refused, or t_init and error) | fixed window error.", "",
         "| case | " + " | ".join(f"anchor {a}" for a in ("3", "5", "9", "12")) + " | fixed mean error (m) |",
         "|---|---|---|---|---|---|"]
for case in cases:
    rows = read_csv(case / "estimates.csv")
    cells, fixed_errors = [], []
    for anchor in ("3", "5", "9", "12"):
        gated = next(r for r in rows if r["anchor_id"] == anchor and r["method"] == GATED)
        fixed = next(r for r in rows if r["anchor_id"] == anchor and r["method"] == FIXED)
        g = (f"gated {number(gated['err_m']):.2f} m at {number(gated['t_init']):.0f} s" if gated["initialized"] == "1"
             else f"refused (PDOP {number(gated['blocked_value']):.1f})")  # the test that held it back, at the end
        fixed_errors.append(number(fixed["err_m"]))
        cells.append(f"{g} / fixed {number(fixed['err_m']):.2f} m")
    lines.append(f"| {case.name} | " + " | ".join(cells) + f" | {sum(fixed_errors) / len(fixed_errors):.2f} |")
# The bias-aware and the certified triggers (docs/method.md), where the config ran them:
# initialized anchors and their mean error per case.
methods = [m for m in ("pdop_closest_point", "dop4_closest_point", "dop4_confidence", "dop4_true", "certified",
                       "fixed_window")
           if any(r["method"] == m for r in read_csv(cases[0] / "estimates.csv"))]
lines += ["", "Every trigger the config ran: initialized anchors of 4, their mean and worst error.", "",
          "| case | " + " | ".join(methods) + " |", "|---|" + "---|" * len(methods)]
for case in cases:
    rows = read_csv(case / "estimates.csv")
    cells = []
    for method in methods:
        errors = [number(r["err_m"]) for r in rows if r["method"] == method and r["initialized"] == "1"]
        cells.append(f"{len(errors)}: {sum(errors) / len(errors):.2f} / {max(errors):.2f} m" if errors else "0")
    lines.append(f"| {case.name} | " + " | ".join(cells) + " |")
# Horizontal and vertical errors apart, without and with the mirror check (docs/method.md):
# initialized anchors of the 32, their median x-y and z error, and how many the check refused.
checked_root = RESULTS / "hanyang_height_check"
if checked_root.exists():
    lines += ["", "x-y and z errors over all 8 cases (32 anchor runs), without and with the mirror check "
              "(`configs/hanyang_height_check.yaml`, results/hanyang_height_check/): initialized, median x-y / z "
              "error, refused as height_unobservable.", "",
              "| trigger | without: init, x-y / z (m) | with the check: init, x-y / z (m), refused |", "|---|---|---|"]

    def pooled(folder, method):
        rows = [r for case in cases for r in read_csv(folder / case.name / "estimates.csv") if r["method"] == method]
        done = [r for r in rows if r["initialized"] == "1"]
        xy = sorted(number(r["err_xy"]) for r in done)
        z = sorted(number(r["err_z"]) for r in done)
        refused = sum(r["status"] == "height_unobservable" for r in rows)
        errors = f"{xy[len(xy) // 2]:.2f} / {z[len(z) // 2]:.2f}" if done else "- / -"
        return len(done), errors, refused

    for method in methods:
        n0, errors0, _ = pooled(root, method)
        n1, errors1, refused = pooled(checked_root, method)
        lines.append(f"| {method} | {n0}, {errors0} | {n1}, {errors1}, {refused} |")
# With each anchor's surveyed height as a prior (sigma 0.1 m) and the horizontal-DOP trigger.
prior_root = RESULTS / "hanyang_height_prior"
if prior_root.exists():
    prior_methods = list(dict.fromkeys(r["method"] for r in read_csv(prior_root / cases[0].name / "estimates.csv")))
    lines += ["", "With each anchor's surveyed height as a prior, sigma 0.1 m (`configs/hanyang_height_prior.yaml`, "
              "results/hanyang_height_prior/), over all 8 cases: initialized of 32, median x-y / z error, mean and "
              "worst error, median t_init, and the latency against the oracle (`latency` of estimates.csv: the median "
              "and 90th percentile over the initialized anchors the oracle reaches; README, summary.md).", "",
              "| trigger | initialized | median x-y / z (m) | mean / worst (m) | median t_init (s) | latency |",
              "|---|---|---|---|---|---|"]
    for method in prior_methods:
        rows = [r for case in cases for r in read_csv(prior_root / case.name / "estimates.csv") if r["method"] == method]
        done = [r for r in rows if r["initialized"] == "1"]
        if not done:
            lines.append(f"| {method} | 0 / {len(rows)} | - | - | - | - |")
            continue
        xy = sorted(number(r["err_xy"]) for r in done)
        z = sorted(number(r["err_z"]) for r in done)
        errors = [number(r["err_m"]) for r in done]
        t = sorted(number(r["t_init"]) for r in done)
        latency = latency_text([number(r["latency"]) for r in done if r["latency"]]) or "-"
        lines.append(f"| {method} | {len(done)} / {len(rows)} | {xy[len(xy) // 2]:.2f} / {z[len(z) // 2]:.2f} | "
                     f"{sum(errors) / len(errors):.2f} / {max(errors):.2f} | {t[len(t) // 2]:.0f} | {latency} |")
(root / "summary.md").write_text("\n".join(lines) + "\n")
print(f"wrote {(root / 'summary.md').relative_to(RESULTS.parent)}")

build = RESULTS.parent / "build" / "hanyang"
fig, axes = plt.subplots(1, 2)
for ax, name in zip(axes, ["LOS_Trajectory_A_Case_1", "NLOS_Trajectory_A_Case_1"]):
    if not (build / name).exists():
        continue
    poses = read_csv(build / name / "poses.csv")
    anchors = read_csv(build / name / "anchors.csv")
    estimates = read_csv(root / name / "estimates.csv")
    ax.plot([number(p["x"]) for p in poses], [number(p["y"]) for p in poses], lw=0.6, color="#888888", label="tag path")
    ax.scatter([number(a["x"]) for a in anchors], [number(a["y"]) for a in anchors], marker="^", s=40, color="k",
               label="anchors (truth)")
    for method, marker, color in [(FIXED, "x", COLORS[FIXED]), (GATED, "o", COLORS[GATED])]:
        chosen = [e for e in estimates if e["method"] == method and e["initialized"] == "1"]
        ax.scatter([number(e["x"]) for e in chosen], [number(e["y"]) for e in chosen], marker=marker, s=30,
                   color=color, label=f"{method} estimates ({len(chosen)}/4)")
    ax.set_title(name.replace("_", " "))
    ax.set_xlabel("x (m)")
    ax.set_aspect("equal", adjustable="datalim")
axes[0].set_ylabel("y (m)")
axes[0].legend(loc="lower left")
save(fig, root / "hanyang_cases.png")
