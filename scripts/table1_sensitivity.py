#!/usr/bin/env python3
"""How sensitive is Table I to the scenario choices of configs/table1.yaml?

Reruns the table with one choice changed at a time (anchorbench run --set) and prints a Markdown
table for docs/table1.md. Usage: /usr/bin/python3 scripts/table1_sensitivity.py [REALIZATIONS]
(default 50; the committed table1 uses 100). Takes about a minute on 2 cores.
"""
import csv
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
BIN = ROOT / "build" / "experiments" / "anchorbench"
CONFIG = ROOT / "configs" / "table1.yaml"
OUT = ROOT / "build" / "sensitivity"

VARIANTS = [
    ("as configured", []),
    ("tunnel 8 m wide", ["scenario.tunnel.width_m=8"]),
    ("tunnel 12 m wide", ["scenario.tunnel.width_m=12"]),
    ("speed 0.4 m/s", ["scenario.trajectory.speed_mps=0.4"]),
    ("speed 1.0 m/s", ["scenario.trajectory.speed_mps=1.0"]),
    ("15% planar runs", ["scenario.trajectory.fraction_planar=0.15"]),
    ("35% planar runs", ["scenario.trajectory.fraction_planar=0.35"]),
    ("planar runs exactly flat", ["scenario.trajectory.planar_vertical_excursion_m=0"]),
    ("planar wobble up to 0.6 m", ["scenario.trajectory.planar_vertical_excursion_m=0.6"]),
    ("10% straight lines", ["scenario.trajectory.fraction_straight=0.1", "scenario.trajectory.fraction_planar=0.15"]),
    ("no tag-position noise", ["scenario.ranging.sigma_position_m=0"]),
    ("symmetric spikes", ["scenario.ranging.outlier_kind=symmetric"]),
    ("NLOS episodes of 30 ranges", ["scenario.ranging.outlier_burst_length=30"]),
    ("rows 2-3 sigma 0.2, 0.3 m", ["rows.1.scenario.ranging.sigma_range_m=0.2", "rows.1.estimator.filter.tau_m=0.4",
                                   "rows.1.estimator.nls.kernel_scale_m=0.2", "rows.2.scenario.ranging.sigma_range_m=0.3",
                                   "rows.2.estimator.filter.tau_m=0.6", "rows.2.estimator.nls.kernel_scale_m=0.3"]),
]


def run(name, overrides, realizations):
    out = OUT / re.sub(r"[^a-z0-9]+", "_", name.lower()).strip("_")
    command = [str(BIN), "run", str(CONFIG), "--out", str(out), "--quiet", "--realizations", str(realizations)]
    for assignment in overrides:
        command += ["--set", assignment]
    subprocess.run(command, check=True)
    summary = {(r["row"], r["method"]): r for r in csv.DictReader(open(out / "summary.csv"))}
    within = re.search(r"(\d+) of (\d+) target cells", (out / "summary.md").read_text())
    return summary, f"{within.group(1)}/{within.group(2)}"


def cell(row, key, digits):
    return f"{float(row[key]):.{digits}f}" if row[key] else "-"


def main():
    realizations = int(sys.argv[1]) if len(sys.argv) > 1 else 50
    attempts = 30 * realizations
    print(f"{realizations} realizations per row; per row: fixed Avg / Med / Ratio %, gated Avg / Init % / Ratio %.\n")
    print("| variant | cells within 25% | " + " | ".join(f"row {r}" for r in "1234") + " |")
    print("|---|---|" + "---|" * 4)
    for name, overrides in VARIANTS:
        summary, within = run(name, overrides, realizations)
        cells = []
        for r in "1234":
            f, g = summary[(r, "fixed_window")], summary[(r, "pdop_closest_point")]
            init_pct = 100.0 * int(g["init"]) / attempts
            cells.append(f"{cell(f, 'avg_m', 2)} / {cell(f, 'med_m', 3)} / {cell(f, 'ratio_pct', 1)}; "
                         f"{cell(g, 'avg_m', 2)} / {init_pct:.0f} / {cell(g, 'ratio_pct', 1)}")
        print(f"| {name} | {within} | " + " | ".join(cells) + " |", flush=True)
    print("| **paper** | | 0.23 / 0.039 / 9.4; 0.13 / 45 / 2.7 | 0.35 / 0.043 / 16.8; 0.10 / 19 / 2.4 | "
          "0.52 / 0.055 / 20.5; 0.15 / 17 / 4.1 | 0.75 / 0.229 / 20.7; 0.34 / 21 / 6.1 |")


if __name__ == "__main__":
    main()
