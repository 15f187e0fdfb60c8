"""Ctrl-C stops a long computation within about a second, even with a Python part that computes
without end on an engine thread (issue 33), and leaves nothing behind."""

import os
import signal
import subprocess
import sys
import time

import pytest

SCRIPT = r"""
import sys, time
import anchorbench as ab
import numpy as np

def endless(p, d):
    while True:  # a part that computes without end
        sum(range(1000))

ab.register_solver("endless", endless)
config = {"realizations": 50, "scenario": {"tunnel": {"length_m": 60, "num_anchors": 3}},
          "estimator": {"solver": "endless", "triggers": ["fixed_window"]}}
print("ready", flush=True)
try:
    ab.run(config, threads=2, progress=False)
except KeyboardInterrupt:
    print("interrupted", flush=True)
    sys.exit(0)
print("finished", flush=True)
"""


@pytest.mark.parametrize("kind", ["python_part", "engine"])
def test_ctrl_c_stops_a_run_within_a_second(kind, tmp_path):
    script = SCRIPT if kind == "python_part" else SCRIPT.replace('"solver": "endless", ', "").replace(
        '"realizations": 50', '"realizations": 100000')
    process = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True, cwd=tmp_path)
    assert process.stdout.readline().strip() == "ready"
    time.sleep(1.5)  # well inside the part, or the engine's units
    sent = time.monotonic()
    process.send_signal(signal.SIGINT)
    try:
        out, _ = process.communicate(timeout=10)
    except subprocess.TimeoutExpired:
        process.kill()
        pytest.fail("Ctrl-C did not stop the run within 10 s")
    assert out.strip() == "interrupted"
    assert time.monotonic() - sent < 2.0
    assert os.listdir(tmp_path) == []
