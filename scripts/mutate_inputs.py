"""Mutated inputs against an anchorbench binary (the sanitizer build in CI): configs, CSV files
and command lines, each a small random change of a valid one. Every case must end in exit 0 or
exit 2 with one line on stderr; a crash, a sanitizer report, exit 3 (internal error) or a hang
fails. Deterministic for a seed. Usage: mutate_inputs.py ANCHORBENCH CASES [SEED]"""
import os
import random
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
        with open(path, "w", encoding="utf-8", errors="surrogateescape") as f:
            f.write(text)
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


failures = crashes = 0
counts = {0: 0, 2: 0}
with tempfile.TemporaryDirectory() as folder:
    for n in range(CASES):
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
        if ok:
            counts[done.returncode] += 1
        else:
            failures += 1
            crashes += done.returncode not in (0, 2, 3)
            print(f"FAIL (exit {done.returncode}): {args}\n{err[-2000:]}")
print(f"mutated inputs: {CASES} cases, {counts[0]} ran, {counts[2]} refused with one line, "
      f"{failures} failed ({crashes} crashes)")
sys.exit(1 if failures else 0)
