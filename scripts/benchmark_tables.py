"""Turns the Google Benchmark JSON files and the two Table I runs of scripts/benchmarks.sh into
the tables of results/benchmarks/ (standard library only). Medians over the repetitions."""
import csv
import json
import os
import platform
import sys

folder = sys.argv[1]


def medians(bench):
    """{name: benchmark entry} of the median aggregate of each benchmark in BENCH.json."""
    with open(os.path.join(folder, bench + ".json")) as f:
        report = json.load(f)
    rows = {}
    for b in report["benchmarks"]:
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        rows[b.get("run_name", b["name"])] = b
    return report["context"], rows


def milliseconds(b):
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b["time_unit"]]
    return b["real_time"] * scale


# Solvers side by side: each against the dense Eigen baseline and against lm_l2 on the same data
# (N samples, outlier share); names are BM_Solver/<solver>/n:<N>/outlier_percent:<P>.
context, compare = medians("bench_compare")
by_data = {}
for name, b in compare.items():
    parts = name.split("/")
    solver = "eigen_dense_ls (baseline)" if parts[0] == "BM_EigenDenseLs" else "/".join(parts[1:-2])
    key = (int(parts[-1].split(":")[1]), int(parts[-2].split(":")[1]))  # (outlier percent, N)
    by_data.setdefault(key, {})[solver] = b
with open(os.path.join(folder, "solvers.csv"), "w", newline="") as f:
    w = csv.writer(f, lineterminator="\n")
    w.writerow(["solver", "samples", "outlier_pct", "time_ms", "x_eigen_dense_ls", "x_lm_l2", "error_m", "iterations"])
    md = ["| solver | samples | outliers | time (ms) | x dense Eigen LS | x lm_l2 | error (m) | iterations |",
          "|---|---|---|---|---|---|---|---|"]
    for outliers, size in sorted(by_data):
        rows = by_data[(outliers, size)]
        base = milliseconds(rows["eigen_dense_ls (baseline)"])
        l2 = milliseconds(rows["lm_l2"])
        for solver, b in rows.items():
            t = milliseconds(b)
            iterations = int(b["solver_iterations"]) if "solver_iterations" in b else ""  # none for the baseline
            fields = [solver, size, outliers, f"{t:.4g}", f"{t / base:.3g}", f"{t / l2:.3g}", f"{b['error_m']:.3g}",
                      iterations]
            w.writerow(fields)
            md.append("| " + " | ".join(str(x) for x in fields[:2]) + f" | {outliers}% | " +
                      " | ".join(str(x) for x in fields[3:]) + " |")
with open(os.path.join(folder, "solvers.md"), "w") as f:
    f.write("Every registered solver and both RANSAC schemes on the same samples (a pass by a wall anchor with "
            "5, 10 and 20% NLOS outliers, bench/bench_compare.cpp); times are medians, ratios within this "
            "run.\n\n")
    f.write("\n".join(md) + "\n")

# The per-sample costs of the other programs.
with open(os.path.join(folder, "micro.csv"), "w", newline="") as f:
    w = csv.writer(f, lineterminator="\n")
    w.writerow(["program", "benchmark", "time", "unit", "counters"])
    for bench in ["bench_solver", "bench_pdop", "bench_filters", "bench_triggers", "bench_front_end", "bench_guidance",
                  "bench_ingest"]:
        _, rows = medians(bench)
        for name, b in rows.items():
            known = {"name", "run_name", "run_type", "repetitions", "repetition_index", "threads", "iterations",
                     "real_time", "cpu_time", "time_unit", "family_index", "per_family_instance_index",
                     "aggregate_name", "aggregate_unit"}
            counters = ";".join(f"{k}={v:.4g}" for k, v in b.items() if k not in known and isinstance(v, (int, float)))
            w.writerow([bench, name, f"{b['real_time']:.4g}", b["time_unit"], counters])

# Table I on 1 and 2 threads: the engine's scaling.
walls = {}
for threads in (1, 2):
    with open(os.path.join(folder, f"table1_threads_{threads}", "manifest.json")) as f:
        walls[threads] = json.load(f)["wall_time_s"]
with open(os.path.join(folder, "table1_threads.csv"), "w", newline="") as f:
    w = csv.writer(f, lineterminator="\n")
    w.writerow(["threads", "wall_time_s", "speedup"])
    for threads in (1, 2):
        w.writerow([threads, f"{walls[threads]:.2f}", f"{walls[1] / walls[threads]:.2f}"])

model = platform.machine()
if os.path.exists("/proc/cpuinfo"):
    with open("/proc/cpuinfo") as f:
        model = next((line.split(":", 1)[1].strip() for line in f if line.startswith("model name")), model)
with open(os.path.join(folder, "machine.md"), "w") as f:
    f.write(f"- CPU: {context.get('num_cpus')} x {model} at {context.get('mhz_per_cpu')} MHz\n")
    f.write(f"- load average at the start: {context.get('load_avg')}\n")
    f.write(f"- date: {context.get('date')}\n")
    f.write(f"- benchmark library build: {context.get('library_build_type')} (Debian's libbenchmark; our code is Release)\n")
