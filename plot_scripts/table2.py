"""Table II analog: anchors' position RMSE per axis, consistency check vs RANSAC, each with plain
NLS (results/table2/attempts.csv, fixed-window attempts), beside the paper's Table II."""
import math

from common import FIXED, RESULTS, number, read_csv

attempts = [a for a in read_csv(RESULTS / "table2" / "attempts.csv") if a["method"] == FIXED and a["initialized"] == "1"]
PAPER = {"consistency": ["0.17 / 0.18", "0.12 / 0.11", "0.35 / 0.34", "0.44 / 0.43"],
         "ransac": ["0.17 / 0.2", "0.12 / 0.13", "0.37 / 0.31", "0.47 / 0.42"]}
lines = ["# Table II analog: consistency check vs RANSAC, each with plain NLS", "",
         "Position RMSE of the fixed-window initializations (all of each anchor's data) over the AMR hall's",
         "covering drives (`configs/table2.yaml`). Paper: experiments 1 / 2 of its Table II.", "",
         "| method | x (m) | y (m) | z (m) | 3D (m) | paper x | paper y | paper z | paper avg |",
         "|---|---|---|---|---|---|---|---|---|"]
for row in ("consistency", "ransac"):
    chosen = [a for a in attempts if a["row"] == row]
    rmse = [math.sqrt(sum(number(a[f"err_{axis}"]) ** 2 for a in chosen) / len(chosen)) for axis in "xyz"]
    total = math.sqrt(sum(number(a["err_m"]) ** 2 for a in chosen) / len(chosen))
    lines.append(f"| {row} ({len(chosen)} anchors) | " + " | ".join(f"{v:.3f}" for v in rmse) + f" | {total:.3f} | "
                 + " | ".join(PAPER[row]) + " |")
(RESULTS / "table2" / "table2.md").write_text("\n".join(lines) + "\n")
print(f"wrote {(RESULTS / 'table2' / 'table2.md').relative_to(RESULTS.parent)}")
