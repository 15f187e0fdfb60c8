"""Shared helpers for the figure scripts: paths, CSV loading, a paper-sized style."""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402

RESULTS = pathlib.Path(__file__).resolve().parent.parent / "results"
sys.path.append(str(RESULTS.parent / "scripts"))
from quantile import latency_text  # noqa: E402,F401  (the tables' one latency cell)

plt.rcParams.update({
    "figure.figsize": (7.0, 2.6),  # a two-column paper figure, in inches
    "figure.dpi": 150,
    "font.size": 8,
    "axes.titlesize": 8,
    "axes.labelsize": 8,
    "legend.fontsize": 7,
    "axes.grid": True,
    "grid.alpha": 0.3,
})
# The trigger names of the paper's two methods, as in the method column of the results.
FIXED, GATED = "fixed_window", "pdop_closest_point"
COLORS = {FIXED: "#d95f02", GATED: "#1b9e77", "paper": "#444444"}


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def number(text):
    """A CSV cell as a float; empty cells (not applicable) become NaN for plotting only."""
    return float(text) if text not in ("", None) else float("nan")


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
    print(f"wrote {path.relative_to(RESULTS.parent)}")
