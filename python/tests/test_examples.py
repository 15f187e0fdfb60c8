"""The examples under examples/python run (small), as a user would start them."""

import os
import subprocess
import sys

import pytest

SOURCE = os.environ.get("ANCHORBENCH_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


def run_example(name, *args):
    return subprocess.run([sys.executable, os.path.join(SOURCE, "examples", "python", name), *map(str, args)],
                          cwd=SOURCE, capture_output=True, text=True, check=True)


def test_the_numpy_solver_example_compares_and_draws(tmp_path):
    done = run_example("numpy_solver.py", "--realizations", 2, "--threads", 2, "--figure", tmp_path / "cdf.png")
    assert "numpy_gauss_newton" in done.stdout and "lm_adaptive" in done.stdout
    assert (tmp_path / "cdf.png").stat().st_size > 1000


def test_the_streaming_example_prints_events_as_they_fire(tmp_path):
    done = run_example("streaming_replay.py", "--config", "configs/tunnel.yaml", "--figure", tmp_path / "replay.png")
    assert (tmp_path / "replay.png").stat().st_size > 1000
    lines = done.stdout.splitlines()
    assert any("pdop_closest_point" in line for line in lines), done.stdout[:500]
    assert any(line.startswith("end") and "fixed_window" in line for line in lines)
