"""The docs state what the code enforces: docs/config.md's Limits table (scripts/config_limits.py)."""

import os
import subprocess
import sys


def test_the_limits_table_is_what_the_loader_enforces():
    source = os.environ.get("ANCHORBENCH_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
    done = subprocess.run([sys.executable, os.path.join(source, "scripts", "config_limits.py"), "--check"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
