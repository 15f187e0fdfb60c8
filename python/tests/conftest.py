"""Shared fixtures: a small table (a few seconds a run), the CLI built beside the module."""

import os
import subprocess

import numpy as np
import pytest

SMALL_TABLE = """seed: 5
realizations: 4
bootstrap_resamples: 50
scenario:
  tunnel: {length_m: 60, width_m: 10, num_anchors: 4}
  trajectory: {kind: random, rate_hz: 5}
  ranging: {sigma_range_m: 0.1, outlier_probability: 0.02}
rows:
  - name: "1"
  - name: "2"
    scenario: {ranging: {sigma_range_m: 0.3}}
"""


@pytest.fixture
def small_yaml(tmp_path):
    path = tmp_path / "small.yaml"
    path.write_text(SMALL_TABLE)
    return path


@pytest.fixture
def cli():
    """Runs the anchorbench executable; returns the completed process."""
    binary = os.environ.get("ANCHORBENCH_CLI")
    if not binary or not os.path.exists(binary):
        pytest.skip("ANCHORBENCH_CLI does not name the anchorbench executable")

    def run(*args, check=True):
        # Not the ASan runtime the sanitizer job preloads into python3: the sanitized CLI carries its
        # own, and two runtimes in one process refuse to start.
        env = {k: v for k, v in os.environ.items() if k != "LD_PRELOAD"}
        return subprocess.run([binary, *map(str, args)], capture_output=True, text=True, check=check, env=env)

    return run


def box_samples(p_world_anchor, n=400, sigma_m=0.05, bias_m=0.3, seed=1):
    """Tag positions in a 10 m box around the origin and noisy biased ranges to an anchor."""
    rng = np.random.default_rng(seed)
    p = rng.uniform([-5, -5, 0], [5, 5, 3], size=(n, 3))
    d = np.linalg.norm(p - np.asarray(p_world_anchor), axis=1) + bias_m + rng.normal(0, sigma_m, n)
    return p, d
