#!/usr/bin/env python3
"""The cost of splitting a run into shards and merging them, against the plain run (issue 15).

Runs Table I plainly, then as N shards one after another (each on the same threads) plus
`anchorbench merge`, for N = 2, 4, 8, and writes DIR/shards.csv:
  shards,units,plain_s,shards_s,merge_s,overhead_pct,same_bytes
overhead_pct = 100 (shards_s + merge_s - plain_s) / plain_s, all measured in this one run (the
plain time is the mean of a run before and one after). same_bytes: the merged summary.csv and
attempts.csv equal the plain run's.
Usage: /usr/bin/python3 scripts/shard_overhead.py ANCHORBENCH DIR [--realizations M]
(scripts/benchmarks.sh runs it; --quick passes a small M)."""
import filecmp
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
CONFIG = ROOT / "configs" / "table1.yaml"


def timed(command):
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def main():
    binary, out = sys.argv[1], pathlib.Path(sys.argv[2])
    extra = sys.argv[3:]  # e.g. --realizations 2
    work = pathlib.Path(tempfile.mkdtemp(prefix="shard_overhead_"))
    try:
        run = [binary, "run", str(CONFIG), "--quiet", "--threads", "2", "--overwrite"] + extra
        plain = [timed(run + ["--out", str(work / "plain")])]
        lines = []
        for n in (2, 4, 8):
            shards_s = sum(timed(run + ["--shard", f"{i}/{n}", "--out", str(work / f"s{n}-{i}")]) for i in range(n))
            merge_s = timed([binary, "merge", str(work / f"merged{n}"), "--quiet"] +
                            [str(work / f"s{n}-{i}") for i in range(n)])
            same = all(filecmp.cmp(work / "plain" / f, work / f"merged{n}" / f, shallow=False)
                       for f in ("attempts.csv", "summary.csv", "summary.md"))
            lines.append((n, shards_s, merge_s, same))
        plain.append(timed(run + ["--out", str(work / "plain")]))
        plain_s = sum(plain) / len(plain)
        units = sum(1 for _ in open(work / "plain" / "attempts.csv")) - 1
        with open(out / "shards.csv", "w") as f:
            f.write("shards,attempts,plain_s,shards_s,merge_s,overhead_pct,same_bytes\n")
            for n, shards_s, merge_s, same in lines:
                overhead = 100.0 * (shards_s + merge_s - plain_s) / plain_s
                f.write(f"{n},{units},{plain_s:.3f},{shards_s:.3f},{merge_s:.3f},{overhead:.1f},{int(same)}\n")
    finally:
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
