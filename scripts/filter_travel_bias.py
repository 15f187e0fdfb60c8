"""The consistency check's travel bias (estimator/include/anchorbench/estimator/consistency_filter.hpp):
the check of Sec. III-B alone, on straight passes of a tag by an anchor (one range per sample,
white noise sigma, no outliers), and the mean of the accepted ranges' noise times the sign of the
range rate, in units of what a solve can measure of the noise the check truncates: the scale q of
the differences of consecutive accepted residuals (RMS over sqrt(2); credible_covariance.hpp's
DifferenceScale, which a slow bias leaves alone) gives g = -E[e sign(rate)] / q as a function of
tau / q, for tau / sigma from 0.25 to 8 and the largest over speeds of 0.3-6 m/s at 10 Hz and
passes 3-8 m off the anchor. ConsistencyFilter::TravelBias holds these numbers (rounded up); the
script prints them. Usage: filter_travel_bias.py [SEED]"""
import sys

import numpy as np

import consistency_check

rng = np.random.default_rng(int(sys.argv[1]) if len(sys.argv) > 1 else 1)


def travel_bias(sigma, tau, speed, lateral, rate=10.0, reseed=10):
    t = np.arange(-60.0, 60.0, 1.0 / rate)
    p = np.stack([speed * t, np.full_like(t, lateral), np.zeros_like(t)], 1)
    distance = np.linalg.norm(p, axis=1)
    noise = sigma * rng.normal(size=len(t))
    ranges = distance + noise
    accepted = consistency_check.accepted(ranges, p, tau, reseed)
    scale = np.sqrt(np.mean(np.diff(noise[accepted]) ** 2) / 2.0)
    return tau / scale, -np.mean(noise[accepted] * np.sign(np.gradient(distance))[accepted]) / scale


for ratio in [0.25, 0.5, 1, 1.5, 2, 3, 5, 8]:
    runs = [[travel_bias(0.1, 0.1 * ratio, speed, lateral) for _ in range(10)]
            for speed in [0.3, 0.6, 1.5, 3.0, 6.0] for lateral in [3.0, 8.0]]
    worst = max(runs, key=lambda r: np.mean([g for _, g in r]))
    print(f"tau / sigma = {ratio}: tau / q = {np.mean([q for q, _ in worst]):.2f}, g = {np.mean([g for _, g in worst]):.3f}")
