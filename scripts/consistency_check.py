"""The consistency check of Sec. III-B as consistency_filter.cpp runs it, for the scripts that
simulate it alone (filter_travel_bias.py, travel_bias_slack.py)."""
import numpy as np


def accepted(ranges, p, tau_m, reseed=10):
    """Indices of the ranges the check accepts: |d_k - d_ref| <= ||p_k - p_ref|| + tau against the
    last accepted one, re-seeded after `reseed` rejections in a row."""
    kept, ref, rejections = [0], 0, 0
    for k in range(1, len(ranges)):
        if abs(ranges[k] - ranges[ref]) <= np.linalg.norm(p[k] - p[ref]) + tau_m or rejections + 1 >= reseed:
            kept.append(k)
            ref, rejections = k, 0
        else:
            rejections += 1
    return np.array(kept)
