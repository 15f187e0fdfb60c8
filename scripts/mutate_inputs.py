"""Mutated inputs against an anchorbench binary (the sanitizer build in CI): configs, CSV files
and command lines, each a small random change of a valid one, and hostile shapes (seeds near the
integer limits, row names with line breaks and commas, alias bombs, tampered chunk stores and
evaluation logs, inputs inside outputs). Every case must end in exit 0 or exit 2 with one line on
stderr; a crash, a sanitizer report, exit 3 (internal error) or a hang fails; a hostile case that
exits 0 must also keep its promise (the seed written back exactly, a resumed or reused run's
bytes those of a clean one, the inputs untouched). Deterministic for a seed.
Usage: mutate_inputs.py ANCHORBENCH CASES [SEED]"""
import filecmp
import glob
import json
import os
import random
import shutil
import subprocess
import sys
import tempfile

BIN, CASES = sys.argv[1], int(sys.argv[2])
rng = random.Random(int(sys.argv[3]) if len(sys.argv) > 3 else 1)

CONFIG = """seed: 1
realizations: 2
bootstrap_resamples: 20
scenario:
  tunnel: {length_m: 60, num_anchors: 3}
  trajectory: {fraction_planar: 0.2}
  ranging: {sigma_range_m: 0.1, outlier_probability: 0.05}
estimator:
  triggers: [fixed_window, pdop_closest_point]
  filter: {tau_m: 0.2}
  trigger: {pdop_threshold: 1}
"""
POSES = "t,tag_id,x,y,z\n" + "".join(f"{k / 10},0,{k / 5},{(k % 7) / 3},{1 + (k % 5) / 4}\n" for k in range(60))
RANGES = "t,tag_id,anchor_id,range\n" + "".join(f"{k / 10},0,{k % 3},{5 + (k % 11) / 7}\n" for k in range(60))
ANCHORS = "anchor_id,x,y,z,bias\n0,3,4,2,0.1\n1,-2,5,3,\n2,6,-1,1,0\n"
WEIRD = ["-1", "0", "1e308", "-1e308", "nan", "inf", ".nan", "", "[]", "{}", "[1, 2", "\x01", "é", "9" * 40,
         "0.0000001", "true", "null", "~", "?", "- a", "&a", "*a", "!!int x", "\t", ":", "'", '"', "\\"]


def mutate(text):
    lines = text.split("\n")
    for _ in range(rng.randint(1, 3)):
        i = rng.randrange(len(lines))
        kind = rng.randrange(6)
        if kind == 0:
            lines[i] = lines[i][: rng.randrange(len(lines[i]) + 1)]  # truncate
        elif kind == 1:
            lines.insert(i, lines[rng.randrange(len(lines))])  # duplicate a line
        elif kind == 2:
            del lines[i]
        elif kind == 3:
            cut = rng.randrange(len(lines[i]) + 1)
            lines[i] = lines[i][:cut] + rng.choice(WEIRD) + lines[i][cut:]
        elif kind == 4:
            lines[i] = " " * rng.randrange(8) + lines[i]  # re-indent
        else:
            lines[i] = "".join(c if rng.random() > 0.1 else rng.choice(",:[]{}-#0") for c in lines[i])
    return "\n".join(lines)


def case(folder, n):
    kind = rng.randrange(4)
    config, poses, ranges, anchors = (os.path.join(folder, f"{n}_{name}") for name in
                                      ("c.yaml", "poses.csv", "ranges.csv", "anchors.csv"))
    files = {config: CONFIG, poses: POSES, ranges: RANGES, anchors: ANCHORS}
    target = [config, poses, ranges, anchors][kind if kind < 3 else rng.randrange(4)]
    files[target] = mutate(files[target])
    for path, text in files.items():
        write(path, text)
    out = os.path.join(folder, f"{n}_out")
    if target == config and rng.random() < 0.5:
        args = ["run", config, "--out", out, "--quiet", "--threads", "1"]
    elif target == config:
        args = ["sweep", config, "--set", "estimator.trigger.pdop_threshold=0.5,1", "--out", out, "--quiet", "--threads", "1"]
    else:
        args = ["replay", "--poses", poses, "--ranges", ranges, "--anchors", anchors, "--out", out]
    if rng.random() < 0.3:  # and a mutated option
        args += rng.choice([["--set", f"scenario.ranging.sigma_range_m={rng.choice(WEIRD)}"],
                            ["--threads", rng.choice(WEIRD)], ["--realizations", rng.choice(WEIRD)],
                            ["--seed", rng.choice(WEIRD)], ["--" + rng.choice(WEIRD)], [rng.choice(WEIRD)]])
        if args[0] == "replay" and args[-2] in ("--threads", "--realizations", "--seed"):
            args = args[:-2]
    return args


SEEDS = ["0", "2147483647", "2147483648", "4294967295", "4294967296", "4294967301", "9223372036854775807",
         "9223372036854775808", "18446744073709551615", "-1", "1e3", "0x10"]
ROW_NAMES = ['"b\\nc"', '"a,b"', '"q\\"x"', '"p|q"', '"\\t"', '""', '"ok"', '"\\r"', "'x,y'"]


def write(path, text):
    with open(path, "w", encoding="utf-8", errors="surrogateescape") as f:
        f.write(text)


def references(folder):
    """A clean run, its chunks as a shard, and a small calibration's log: what tampering is judged against."""
    config = os.path.join(folder, "ref.yaml")
    write(config, CONFIG)
    run = lambda *a: subprocess.run([BIN, *a], capture_output=True, timeout=300, check=True)
    run("run", config, "--out", os.path.join(folder, "ref_run"), "--quiet", "--threads", "1")
    run("run", config, "--shard", "0/1", "--out", os.path.join(folder, "ref_shard"), "--quiet", "--threads", "1")
    write(os.path.join(folder, "table.yaml"), "base: ref.yaml\nrows:\n  - name: a\n    paper:\n"
          "      fixed: {avg_m: 0.2, med_m: 0.05, init: 6, gt1m: 1, ratio_pct: 5}\n"
          "      gated: {avg_m: 0.1, med_m: 0.05, init: 3, gt1m: 0, ratio_pct: 0}\n")
    write(os.path.join(folder, "cal.yaml"), "experiment: table.yaml\nseed: 11\nrealizations: 2\nverify_seeds: [3]\n"
          "global: {algorithm: GN_DIRECT_L, max_evaluations: 5}\nlocal: {algorithm: LN_SBPLX, max_evaluations: 2}\n"
          "parameters:\n  - {key: scenario.tunnel.width_m, min: 6, max: 14, provenance: a test}\n")
    run("calibrate", os.path.join(folder, "cal.yaml"), "--out", os.path.join(folder, "ref_cal"), "--quiet", "--threads", "1")
    os.remove(os.path.join(folder, "table.calibrated.yaml"))


def hostile(folder, n):
    """(args, check): a hostile case, and what must hold if it exits 0 (None: nothing more)."""
    config = os.path.join(folder, "ref.yaml")
    out = os.path.join(folder, f"{n}_out")
    kind = rng.randrange(6)
    if kind == 0:  # seeds near the integer limits, on the command line or in the file
        seed = rng.choice(SEEDS)
        if rng.random() < 0.5:
            args = ["run", config, "--seed", seed, "--realizations", "1", "--out", out, "--quiet"]
        else:
            path = os.path.join(folder, f"{n}_seed.yaml")
            write(path, f"base: ref.yaml\nrealizations: 1\nseed: {seed}\n")
            args = ["run", path, "--out", out, "--quiet"]
        def check():
            manifest = json.load(open(os.path.join(out, "manifest.json")))
            return str(manifest["seed"]) == seed and str(manifest["resolved_config"]["seed"]) == seed
        return args, check
    if kind == 1:  # row names that would break a CSV line or a Markdown table
        path = os.path.join(folder, f"{n}_rows.yaml")
        write(path, f"base: ref.yaml\nrealizations: 1\nrows:\n  - name: {rng.choice(ROW_NAMES)}\n")
        return ["run", path, "--out", out, "--quiet"], None
    if kind == 2:  # an alias bomb, of unknown keys or inside a known section
        depth, width = rng.randint(4, 12), rng.randint(2, 9)
        text = "a0: &a0 [" + ", ".join(["x"] * width) + "]\n"
        for i in range(1, depth + 1):
            text += f"a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * width) + "]\n"
        if rng.random() < 0.5:
            text += f"scenario: {{tag_offsets_m: *a{depth}}}\n"
        path = os.path.join(folder, f"{n}_bomb.yaml")
        write(path, text)
        return ["run", path, "--out", out, "--quiet"], None
    if kind == 3:  # a tampered chunk store, resumed: recomputed to the clean run's bytes
        store = out + ".chunks"
        os.makedirs(store)
        blocks = []  # the store's file: each chunk a block `chunk,<index>,<bytes>,` and its text
        for chunk in sorted(glob.glob(os.path.join(folder, "ref_shard", "chunk-*.csv"))):
            text = open(chunk, "rb").read()
            index = int(os.path.basename(chunk)[len("chunk-"):-len(".csv")])
            blocks.append(b"chunk,%d,%d,\n" % (index, len(text)) + text)
        plan = open(os.path.join(folder, "ref_shard", "shard.csv")).read().split("\n")[1].split(",")[5]
        write(os.path.join(store, "plan.csv"), f"identity,chunks,units\n{plan},0,0\n")
        victim = rng.randrange(len(blocks))
        blocks[victim] = mutate(blocks[victim].decode()).encode()
        with open(os.path.join(store, "chunks.csv"), "wb") as f:
            f.write(b"".join(blocks))
        check = lambda: all(filecmp.cmp(os.path.join(out, f), os.path.join(folder, "ref_run", f), shallow=False)
                            for f in ("attempts.csv", "summary.csv"))
        return ["run", config, "--out", out, "--resume", "--quiet", "--threads", "1"], check
    if kind == 4:  # a tampered evaluation log, reused: refused, or the clean calibration's bytes
        log = os.path.join(folder, f"{n}_log.csv")
        write(log, mutate(open(os.path.join(folder, "ref_cal", "evaluations.csv")).read()))
        calibrated = os.path.join(folder, "table.calibrated.yaml")
        if os.path.exists(calibrated):
            os.remove(calibrated)
        check = lambda: filecmp.cmp(os.path.join(out, "evaluations.csv"),
                                    os.path.join(folder, "ref_cal", "evaluations.csv"), shallow=False)
        return ["calibrate", os.path.join(folder, "cal.yaml"), "--out", out, "--reuse", log, "--quiet"], check
    # an input inside the output: refused, and the input still there
    os.makedirs(out, exist_ok=True)
    inside = os.path.join(out, "in.yaml")
    write(inside, "base: ../ref.yaml\nrealizations: 1\n")
    choice = rng.randrange(3)
    if choice == 0:
        args = ["run", inside, "--out", out, "--overwrite", "--quiet"]
    elif choice == 1:
        outer = os.path.join(folder, f"{n}_outer.yaml")
        write(outer, f"base: {n}_out/in.yaml\n")
        args = ["run", outer, "--out", out, "--overwrite", "--quiet"]
    else:
        log = os.path.join(folder, "log_for_trace")
        args = ["replay", "--poses", os.path.join(log, "poses.csv"), "--ranges", os.path.join(log, "ranges.csv"),
                "--out", out, "--trace", os.path.join(out, "in.yaml"), "--overwrite", "--quiet"]
    return args, lambda: os.path.exists(inside) and "ref.yaml" in open(inside).read()


failures = crashes = 0
counts = {0: 0, 2: 0}
with tempfile.TemporaryDirectory() as folder:
    references(folder)
    subprocess.run([BIN, "simulate", os.path.join(folder, "ref.yaml"), "--out", os.path.join(folder, "log_for_trace")],
                   capture_output=True, check=True)
    for n in range(CASES):
        check = None
        if rng.random() < 0.4:
            args, check = hostile(folder, n)
        else:
            args = case(folder, n)
        try:
            done = subprocess.run([BIN] + args, capture_output=True, timeout=60)
        except subprocess.TimeoutExpired:
            print(f"FAIL (hang): {args}")
            failures += 1
            continue
        err = done.stderr.decode("utf-8", "replace")
        ok = done.returncode in (0, 2) and "Sanitizer" not in err and "runtime error" not in err
        if done.returncode == 2:
            ok = ok and err.count("\n") == 1
        if ok and done.returncode == 0 and check is not None and not check():
            ok = False
            err += "\n(exit 0, but the promise of the case does not hold)"
        if ok:
            counts[done.returncode] += 1
        else:
            failures += 1
            crashes += done.returncode not in (0, 2, 3)
            print(f"FAIL (exit {done.returncode}): {args}\n{err[-2000:]}")
print(f"mutated inputs: {CASES} cases, {counts[0]} ran, {counts[2]} refused with one line, "
      f"{failures} failed ({crashes} crashes)")
sys.exit(1 if failures else 0)
