#!/usr/bin/env python3
"""Every trigger's cost on two long multi-tag logs, against the paper's: writes replay_triggers.csv.

A simulated hall of 8 anchors is ranged by 3 tags at 100 Hz for 135 s (324,000 ranges, with the
biases real radios have): `hall_3d`, a path that climbs and falls 0.8 m, and `hall_flat`, the
tags in one plane at a height that wanders 5 cm (a ground robot: certified refuses again and
again the anchors whose mirror fits about as well, and tests every alternative of the others). Each log is replayed once per
trigger with the defaults for real logs (`anchorbench replay --quiet`, one trigger each), and
once with the default trigger set (`defaults`). The time is the replay's wall time, best of
REPEATS, and the ratio is against pdop_closest_point's on the same log in the same run.

    replay_triggers.py BIN OUT_FOLDER [REPEATS]
"""
import csv
import os
import subprocess
import sys
import tempfile
import time

BIN, OUT = sys.argv[1], sys.argv[2]
REPEATS = int(sys.argv[3]) if len(sys.argv) > 3 else 3
TRIGGERS = ["pdop_closest_point", "fixed_window", "dop4_closest_point", "hdop_closest_point", "pdop_ls", "pdop_nls",
            "dop4_confidence", "certified", "sample_count", "timeout", "defaults"]
LOG_3D = """seed: 3
scenario:
  environment: hall
  tag_offsets_m: [[0, 0, 0], [0.3, 0.2, 0.1], [-0.2, 0.25, 0.05]]
  hall: {length_m: 12, width_m: 8, height_m: 4, num_anchors: 8, anchor_height_min_m: 0.5, anchor_height_max_m: 3.5}
  trajectory: {kind: random, height_m: 1.5, vertical_excursion_m: 0.8, hall_duration_s: 135, rate_hz: 100,
               min_period_s: 10, max_period_s: 40}
  ranging: {sigma_range_m: 0.05, outlier_probability: 0.01, antenna_bias_m: 0.05, link_offset_m: 0.1}
"""
LOG_FLAT = (LOG_3D.replace("[[0, 0, 0], [0.3, 0.2, 0.1], [-0.2, 0.25, 0.05]]", "[[0, 0, 0], [0.3, 0.2, 0], [-0.2, 0.25, 0]]")
            .replace("vertical_excursion_m: 0.8", "vertical_excursion_m: 0.05"))
LOGS = {"hall_3d": LOG_3D, "hall_flat": LOG_FLAT}

seconds, ranges = {}, {}
with tempfile.TemporaryDirectory() as folder:
    for name, text in LOGS.items():
        config = os.path.join(folder, f"{name}.yaml")
        open(config, "w").write(text)
        subprocess.run([BIN, "simulate", config, "--out", os.path.join(folder, name)], check=True,
                       stdout=subprocess.DEVNULL)
        ranges[name] = sum(1 for _ in open(os.path.join(folder, name, "ranges.csv"))) - 1
    for trigger in TRIGGERS:
        trigger_config = os.path.join(folder, f"{trigger}.yaml")
        open(trigger_config, "w").write("{}\n" if trigger == "defaults" else f"estimator: {{triggers: [{trigger}]}}\n")
    for _ in range(REPEATS):  # interleaved, so the machine's noise falls on every trigger alike
        for name in LOGS:
            log = os.path.join(folder, name)
            for trigger in TRIGGERS:
                start = time.perf_counter()
                subprocess.run([BIN, "replay", "--quiet", "--poses", os.path.join(log, "poses.csv"), "--ranges",
                                os.path.join(log, "ranges.csv"), "--config", os.path.join(folder, f"{trigger}.yaml")],
                               check=True, stdout=subprocess.DEVNULL)
                elapsed = time.perf_counter() - start
                seconds[name, trigger] = min(seconds.get((name, trigger), elapsed), elapsed)

os.makedirs(OUT, exist_ok=True)
with open(os.path.join(OUT, "replay_triggers.csv"), "w", newline="") as f:
    out = csv.writer(f, lineterminator="\n")
    out.writerow(["log", "trigger", "ranges", "anchors", "tags", "seconds", "ratio_to_paper"])
    for name in LOGS:
        for trigger in TRIGGERS:
            out.writerow([name, trigger, ranges[name], 8, 3, f"{seconds[name, trigger]:.3f}",
                          f"{seconds[name, trigger] / seconds[name, 'pdop_closest_point']:.2f}"])
print(f"wrote {os.path.join(OUT, 'replay_triggers.csv')}")
