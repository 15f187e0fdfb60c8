#!/usr/bin/env python3
"""What spreading Table I over processes costs, against the plain run (issue 15).

In one session: the plain run (2 threads), the same run as N shards one after another (2 threads
each) plus `anchorbench merge` for N = 2, 4, 8, and as MPI jobs of anchorbench-mpi (where it is
built): 2 ranks of 2 threads (one worker: the coordinator's cost alone) and 3 ranks of 1 thread
(two workers). Writes DIR/cluster.csv:
  way,processes,threads,units,chunks,attempts_bytes,plain_s,wall_s,merge_s,overhead_pct,same_bytes
wall_s: the shards one after another, or the mpirun job; overhead_pct = 100 (wall_s + merge_s -
plain_s) / plain_s; plain_s is the mean of a plain run before and one after. same_bytes: the
results' attempts.csv, summary.csv and summary.md equal the plain run's. units, chunks and
attempts_bytes (attempts.csv's size) feed the cost model of docs/cluster.md.
Usage: /usr/bin/python3 scripts/cluster_overhead.py ANCHORBENCH DIR [--realizations M]
(scripts/benchmarks.sh runs it; --quick passes a small M)."""
import filecmp
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
CONFIG = ROOT / "configs" / "table1.yaml"
# The paper's two columns (the engine's cost, as rounds before the certified trigger measured it;
# benchmarks.sh runs the same for the thread speed-up): a fifth of the time of all three.
PAPER_COLUMNS = ["--set", "estimator.triggers=[fixed_window,pdop_closest_point]"]
FILES = ("attempts.csv", "summary.csv", "summary.md")
CHUNKS_PER_EXPERIMENT, MAX_CHUNK_UNITS = 256, 64  # engine/plan.hpp


def timed(command):
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def same(a, b):
    return all(filecmp.cmp(a / f, b / f, shallow=False) for f in FILES)


def main():
    binary, out = sys.argv[1], pathlib.Path(sys.argv[2])
    extra = sys.argv[3:]  # e.g. --realizations 2
    mpi_binary = pathlib.Path(binary).with_name("anchorbench-mpi")
    work = pathlib.Path(tempfile.mkdtemp(prefix="cluster_overhead_"))
    try:
        def run(*args, threads=2):
            return ([binary, "run", str(CONFIG), "--quiet", "--threads", str(threads), "--overwrite"] + PAPER_COLUMNS +
                    extra + list(args))
        plain = [timed(run("--out", str(work / "plain")))]
        measured = []
        for n in (2, 4, 8):
            shards = [work / f"s{n}-{i}" for i in range(n)]
            wall_s = sum(timed(run("--shard", f"{i}/{n}", "--out", str(shard))) for i, shard in enumerate(shards))
            merge_s = timed([binary, "merge", str(work / f"merged{n}"), "--quiet"] + [str(s) for s in shards])
            measured.append(("shards", n, 2, wall_s, merge_s, same(work / "plain", work / f"merged{n}")))
        if mpi_binary.exists() and shutil.which("mpirun"):
            for ranks, threads in ((2, 2), (3, 1)):
                folder = work / f"mpi{ranks}"
                wall_s = timed(["mpirun", "--allow-run-as-root", "--oversubscribe", "--bind-to", "none", "-n", str(ranks),
                                str(mpi_binary)] +
                               run("--out", str(folder), threads=threads)[1:])
                measured.append(("mpi", ranks, threads, wall_s, 0.0, same(work / "plain", folder)))
        plain.append(timed(run("--out", str(work / "plain"))))
        plain_s = sum(plain) / len(plain)
        attempts = work / "plain" / "attempts.csv"
        with open(attempts) as f:
            next(f)
            units = len({tuple(line.split(",", 2)[:2]) for line in f})  # (row, realization) pairs
        chunks = -(-units // min(MAX_CHUNK_UNITS, -(-units // CHUNKS_PER_EXPERIMENT)))
        with open(out / "cluster.csv", "w") as f:
            f.write("way,processes,threads,units,chunks,attempts_bytes,plain_s,wall_s,merge_s,overhead_pct,same_bytes\n")
            for way, processes, threads, wall_s, merge_s, equal in measured:
                overhead = 100.0 * (wall_s + merge_s - plain_s) / plain_s
                f.write(f"{way},{processes},{threads},{units},{chunks},{os.path.getsize(attempts)},{plain_s:.3f},"
                        f"{wall_s:.3f},{merge_s:.3f},{overhead:.1f},{int(equal)}\n")
    finally:
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
