#!/usr/bin/python3
"""What the Python front costs: writes python.csv into a benchmark folder.

A simulated Table I realization (30 anchors, 500 s) is tiled end to end, shifted by 501 s per
copy, into a log of about RANGES ranges. The same log, with the same two triggers
(fixed_window, pdop_closest_point), goes through:
  cli_replay       `anchorbench replay` on the CSV files (it reads them twice: checked, then streamed);
  python_replay    anchorbench.replay on the same files (the same C++ path, from Python);
  python_batch     FrontEnd.add_poses / add_ranges on numpy arrays already in memory, in batches of
                   one 10 s window at a time (poses, then ranges), then finish;
  python_single    FrontEnd.add_pose / add_range, one Python call a row, on the first 100,000 ranges.
Then the cost per attempt of a solver written in numpy (examples/python's Gauss-Newton) against
lm_adaptive in the Monte Carlo: Table I's fixed window, 3 realizations a row, one thread
(timing.csv's us_per_attempt: the whole pass of an attempt, filter and trigger included).

    python_overhead.py BIN OUT_FOLDER [RANGES]     (PYTHONPATH holding the built module)
"""
import csv
import io
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

import anchorbench as ab

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "examples", "python"))
from numpy_solver import gauss_newton  # noqa: E402

CONFIG = {"estimator": {"triggers": ["fixed_window", "pdop_closest_point"]}}


def tiled_log(ranges_wanted):
    """(poses, ranges) structured arrays of a Table I realization tiled to about `ranges_wanted` ranges."""
    log = ab.simulate("configs/table1.yaml")
    poses = np.genfromtxt(io.StringIO(log.text("poses.csv")), delimiter=",", names=True)
    ranges = np.genfromtxt(io.StringIO(log.text("ranges.csv")), delimiter=",", names=True)
    copies = max(1, round(ranges_wanted / len(ranges)))
    shift = 501.0
    tile = lambda a: np.concatenate([np.array(a, copy=True) for _ in range(copies)])
    poses_all, ranges_all = tile(poses), tile(ranges)
    for k in range(copies):
        poses_all["t"][k * len(poses):(k + 1) * len(poses)] += k * shift
        ranges_all["t"][k * len(ranges):(k + 1) * len(ranges)] += k * shift
    return poses_all, ranges_all


def write_csv(path, array, columns):
    with open(path, "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(columns)
        for row in array:
            writer.writerow([repr(float(row[c])) if c not in ("tag_id", "anchor_id") else int(row[c]) for c in columns])


def timed(work):
    start = time.perf_counter()
    work()
    return time.perf_counter() - start


def feed_batches(poses, ranges, window_s=10.0):
    front_end = ab.FrontEnd(CONFIG)
    edges = np.arange(poses["t"][0], poses["t"][-1] + window_s, window_s)
    p_cut, r_cut = np.searchsorted(poses["t"], edges), np.searchsorted(ranges["t"], edges)
    p_xyz = np.column_stack([poses["x"], poses["y"], poses["z"]])
    for k in range(len(edges) - 1):
        ps, pe, rs, re_ = p_cut[k], p_cut[k + 1], r_cut[k], r_cut[k + 1]
        front_end.add_poses(poses["t"][ps:pe], poses["tag_id"][ps:pe].astype(np.int32), p_xyz[ps:pe])
        front_end.add_ranges(ranges["t"][rs:re_], ranges["tag_id"][rs:re_].astype(np.int32),
                             ranges["anchor_id"][rs:re_].astype(np.int32), ranges["range"][rs:re_])
    front_end.finish(float(max(poses["t"][-1], ranges["t"][-1])))
    return len(front_end.take_events())


def feed_single(poses, ranges, count):
    front_end = ab.FrontEnd(CONFIG)
    ranges = ranges[:count]
    poses = poses[poses["t"] <= ranges["t"][-1] + 1.0]
    rows = sorted([(t, 0, i) for i, t in enumerate(poses["t"])] + [(t, 1, i) for i, t in enumerate(ranges["t"])])
    add_pose, add_range = front_end.add_pose, front_end.add_range
    start = time.perf_counter()
    for _, kind, i in rows:
        if kind == 0:
            p = poses[i]
            add_pose(float(p["t"]), int(p["tag_id"]), (float(p["x"]), float(p["y"]), float(p["z"])))
        else:
            r = ranges[i]
            add_range(float(r["t"]), int(r["tag_id"]), int(r["anchor_id"]), float(r["range"]))
    return time.perf_counter() - start, len(rows)


def solver_costs():
    ab.register_solver("numpy_gauss_newton", gauss_newton)
    costs = {}
    for solver in ["lm_adaptive", "numpy_gauss_newton"]:
        result = ab.run("configs/table1.yaml", realizations=3, threads=1,
                        overrides=[f"estimator.solver={solver}", "estimator.triggers=[fixed_window]"])
        timing = result.timing
        costs[solver] = float((timing["us_per_attempt"] * timing["attempts"]).sum() / timing["attempts"].sum())
    return costs


def main():
    binary, out_folder = sys.argv[1], sys.argv[2]
    wanted = int(float(sys.argv[3])) if len(sys.argv) > 3 else 1_000_000
    poses, ranges = tiled_log(wanted)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        poses_csv, ranges_csv, config = (os.path.join(tmp, n) for n in ("poses.csv", "ranges.csv", "config.yaml"))
        write_csv(poses_csv, poses, ["t", "tag_id", "x", "y", "z"])
        write_csv(ranges_csv, ranges, ["t", "tag_id", "anchor_id", "range"])
        with open(config, "w") as f:
            f.write("estimator:\n  triggers: [fixed_window, pdop_closest_point]\n")
        cli_s = timed(lambda: subprocess.run([binary, "replay", "--quiet", "--poses", poses_csv, "--ranges", ranges_csv,
                                              "--config", config], check=True, stdout=subprocess.DEVNULL))
        replay_s = timed(lambda: ab.replay(poses_csv, ranges_csv, config=config))
    batch_s = timed(lambda: feed_batches(poses, ranges))
    single_s, single_rows = feed_single(poses, ranges, min(100_000, len(ranges)))
    n = len(ranges)
    rows.append(["cli_replay", n, f"{cli_s:.3f}", f"{cli_s / n * 1e6:.3f}", "1.00"])
    rows.append(["python_replay", n, f"{replay_s:.3f}", f"{replay_s / n * 1e6:.3f}", f"{replay_s / cli_s:.2f}"])
    rows.append(["python_batch", n, f"{batch_s:.3f}", f"{batch_s / n * 1e6:.3f}", f"{batch_s / cli_s:.2f}"])
    rows.append(["python_single", single_rows, f"{single_s:.3f}", f"{single_s / single_rows * 1e6:.3f}",
                 f"{(single_s / single_rows) / (cli_s / n):.2f}"])
    costs = solver_costs()
    for solver, us in costs.items():
        rows.append([f"solver_{solver}", "", "", f"{us:.1f}", f"{us / costs['lm_adaptive']:.2f}"])
    with open(os.path.join(out_folder, "python.csv"), "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(["way", "rows", "seconds", "us_per_row", "ratio"])
        writer.writerows(rows)


if __name__ == "__main__":
    main()
