#!/usr/bin/env python3
"""Replay throughput and peak memory on long logs: writes replay.csv into a benchmark folder.

A simulated Table I realization (30 anchors, 500 s) is tiled end to end, shifted by 501 s per copy,
into logs of about SIZES ranges; each is replayed once (`anchorbench replay --quiet`) and timed.
Peak memory is the replay process's maximum resident set (getrusage of the child), so a flat value
across sizes shows the replay streams instead of loading the log.

    replay_throughput.py BIN OUT_FOLDER SIZE [SIZE ...]
"""
import csv
import os
import resource
import subprocess
import sys
import tempfile
import time


def tile(src, dst, copies, shift_s):
    with open(src) as f:
        header = f.readline()
        rows = [line.rstrip("\n").split(",", 1) for line in f if line.strip()]
    with open(dst, "w") as out:
        out.write(header)
        for k in range(copies):
            offset = k * shift_s
            out.writelines(f"{float(t) + offset:.6f},{rest}\n" for t, rest in rows)
    return len(rows) * copies


def replay(binary, poses, ranges):
    """Wall time and peak resident memory (MB) of one replay, run alone as a child."""
    start = time.perf_counter()
    subprocess.run([binary, "replay", "--quiet", "--poses", poses, "--ranges", ranges],
                   check=True, stdout=subprocess.DEVNULL)
    wall_s = time.perf_counter() - start
    peak_kb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss  # the largest child so far
    return wall_s, peak_kb / 1024.0


def main():
    binary, out_folder, sizes = sys.argv[1], sys.argv[2], [int(float(s)) for s in sys.argv[3:]]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        sim = os.path.join(tmp, "sim")
        subprocess.run([binary, "simulate", "configs/table1.yaml", "--out", sim], check=True, stdout=subprocess.DEVNULL)
        with open(os.path.join(sim, "ranges.csv")) as f:
            per_copy = sum(1 for _ in f) - 1
        for size in sorted(sizes):  # ascending, so each child's peak is the largest so far
            copies = max(1, round(size / per_copy))
            poses, ranges = os.path.join(tmp, "poses.csv"), os.path.join(tmp, "ranges.csv")
            tile(os.path.join(sim, "poses.csv"), poses, copies, 501.0)
            n_ranges = tile(os.path.join(sim, "ranges.csv"), ranges, copies, 501.0)
            megabytes = (os.path.getsize(poses) + os.path.getsize(ranges)) / 1e6
            wall_s, peak_mb = replay(binary, poses, ranges)
            rows.append({"ranges": n_ranges, "file_mb": f"{megabytes:.1f}", "wall_s": f"{wall_s:.2f}",
                         "ranges_per_s": f"{n_ranges / wall_s:.0f}", "peak_rss_mb": f"{peak_mb:.1f}"})
            os.remove(poses)
            os.remove(ranges)
    with open(os.path.join(out_folder, "replay.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()
