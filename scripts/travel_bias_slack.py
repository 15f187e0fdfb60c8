#!/usr/bin/env python3
"""The consistency check's travel bias against the slack of each sample: writes slack.csv.

The check of Sec. III-B accepts a range when |d_k - d_ref| <= ||p_k - p_ref|| + tau. Where the tag
moves straight towards or away from the anchor, ||p_k - p_ref|| equals the change of the true range
and the check truncates the noise's differences at tau on one side (the travel bias,
ConsistencyFilter::TravelBias). Any sideways motion adds a slack s = ||p_k - p_ref|| - |r_k - r_ref|
>= 0 to tau, and the truncation, and so the bias, shrinks. The certificate's term takes each
accepted sample's bias as the check's table at (tau + s) / q (q: DifferenceScale), and uses their
RMS over the samples (credible_covariance.hpp, TravelBiasOf).

This script checks that bound on what it bounds: the check alone on a ground robot's wandering
paths (10 Hz, 0.3-2 m/s, a heading that drifts, 10-20 m from the anchor, white noise 0.05 m,
tau = 0.1 m: the AMR hall's), the accepted noise times the sign of the range rate, by slack. Each
row: the slack bin, the samples in it, the measured bias and its standard error, and the table's
bound at the bin's mean slack and at zero slack (the term before the slack). The last row, `all`,
compares the whole run's measured bias with the RMS and the mean of the per-sample bounds.
The table is read from estimator/src/consistency_filter.cpp, the one place it is kept.

    travel_bias_slack.py OUT_FOLDER [SEED]
"""
import csv
import os
import re
import sys

import numpy as np

import consistency_check

OUT = sys.argv[1]
rng = np.random.default_rng(int(sys.argv[2]) if len(sys.argv) > 2 else 2)
SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "estimator", "src", "consistency_filter.cpp")
text = open(SOURCE).read()
RATIO = [float(x) for x in re.search(r"kRatio\[\] = \{([^}]*)\}", text).group(1).split(",")]
BIAS = [float(x) for x in re.search(r"kBias\[\] = \{([^}]*)\}", text).group(1).split(",")]
SIGMA_M, TAU_M, RATE_HZ, SAMPLES, RUNS, RESEED = 0.05, 0.1, 10.0, 20000, 40, 10


def bound(slack_m, q_m):  # ConsistencyFilter::TravelBias(q, slack): g((tau + s) / q) q, 0 beyond the table
    return np.interp((TAU_M + slack_m) / q_m, RATIO, BIAS, right=0.0) * q_m


def run():
    speed = rng.uniform(0.3, 2.0)
    heading = np.cumsum(rng.normal(0.0, 0.05, SAMPLES))
    p = np.cumsum(np.stack([np.cos(heading), np.sin(heading)], 1) * speed / RATE_HZ, 0)
    p -= p.mean(0)
    anchor = np.array([rng.uniform(-5.0, 5.0), 15.0 + rng.uniform(-5.0, 5.0)])
    r = np.linalg.norm(p - anchor, axis=1)
    noise = SIGMA_M * rng.normal(size=SAMPLES)
    d = r + noise
    accepted = consistency_check.accepted(d, p, TAU_M, RESEED)
    q = np.sqrt(np.mean(np.diff(noise[accepted]) ** 2) / 2.0)
    prev, cur = accepted[:-1], accepted[1:]
    slack = np.maximum(np.linalg.norm(p[cur] - p[prev], axis=1) - np.abs(r[cur] - r[prev]), 0.0)
    return slack, -noise[cur] * np.sign(r[cur] - r[prev]), np.full(len(cur), q)


slack, bias, q = (np.concatenate(parts) for parts in zip(*(run() for _ in range(RUNS))))
q_m = float(q.mean())
os.makedirs(OUT, exist_ok=True)
with open(os.path.join(OUT, "slack.csv"), "w", newline="") as f:
    out = csv.writer(f, lineterminator="\n")
    out.writerow(["slack_from_m", "slack_to_m", "samples", "measured_m", "measured_se_m", "bound_m", "bound_without_slack_m"])
    edges = [0.0, 0.005, 0.01, 0.02, 0.04, 0.08, 0.2]
    for low, high in zip(edges[:-1], edges[1:]):
        inside = (slack >= low) & (slack < high)
        out.writerow([low, high, int(inside.sum()), f"{bias[inside].mean():.5f}",
                      f"{bias[inside].std() / np.sqrt(inside.sum()):.5f}", f"{bound(slack[inside].mean(), q_m):.5f}",
                      f"{bound(0.0, q_m):.5f}"])
    per_sample = bound(slack, q)
    out.writerow(["all", "rms", len(bias), f"{bias.mean():.5f}", f"{bias.std() / np.sqrt(len(bias)):.5f}",
                  f"{np.sqrt(np.mean(per_sample ** 2)):.5f}", f"{bound(0.0, q_m):.5f}"])
    out.writerow(["all", "mean", len(bias), f"{bias.mean():.5f}", f"{bias.std() / np.sqrt(len(bias)):.5f}",
                  f"{per_sample.mean():.5f}", f"{bound(0.0, q_m):.5f}"])
print(f"wrote {os.path.join(OUT, 'slack.csv')}")
