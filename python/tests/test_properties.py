"""Mutated input against the Python API and the bag tool (issue 33), as property tests: whatever the
arguments, a call returns or raises InputError with one line; never another exception, a crash
or a hang. Hypothesis draws the cases (Debian's python3-hypothesis), derandomized: the same cases on
every run."""

import math

import numpy as np
import pytest

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import HealthCheck, given, settings, strategies as st  # noqa: E402

import anchorbench as ab  # noqa: E402
from conftest import box_samples  # noqa: E402

SETTINGS = settings(max_examples=60, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
WEIRD = st.one_of(st.integers(min_value=-2**70, max_value=2**70), st.floats(allow_nan=True, allow_infinity=True),
                  st.text(max_size=12), st.booleans(), st.none(), st.lists(st.integers(), max_size=3),
                  st.sampled_from([1e308, -1e308, 1e-320, 2**31, -2**31 - 1, "1e300", "~", "nan", "[1, 2"]))


def one_line(error: BaseException) -> None:
    assert "\n" not in str(error), str(error)


def numeric_keys():
    """Every numeric config key: the docs' Limits table's own list (scripts/config_limits.py)."""
    import importlib.util
    from pathlib import Path

    script = Path(__file__).resolve().parents[2] / "scripts" / "config_limits.py"
    spec = importlib.util.spec_from_file_location("config_limits", script)
    config_limits = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(config_limits)
    return sorted(key for key, _ in config_limits.numeric_keys())


KEYS = numeric_keys()


@SETTINGS
@given(key=st.sampled_from(KEYS), value=WEIRD)
def test_any_value_of_any_key_loads_or_is_one_line(key, value):
    """Every numeric key has a finite range: a value loads within it or is refused naming the key."""
    try:
        config = ab.load_config({"navigation": {}}, overrides=[f"{key}={value}"])
    except ab.InputError as error:
        one_line(error)
        return
    import yaml

    loaded = yaml.safe_load(config.yaml)
    for part in key.split("."):
        loaded = loaded[part]
    assert isinstance(loaded, (int, float)) and math.isfinite(loaded) and abs(loaded) <= 1e12, (key, loaded)


@SETTINGS
@given(key=st.sampled_from(KEYS), scale=st.sampled_from([0.0, 1e-9, 1e3, 1e5, 1e6]))
def test_extreme_values_that_load_give_finite_tables_or_one_line(key, scale):
    """A value at the edge of its range either runs to finite tables or is refused before any work."""
    config = {"realizations": 1, "bootstrap_resamples": 10, "navigation": {},
              "scenario": {"tunnel": {"length_m": 40, "num_anchors": 3}, "trajectory": {"rate_hz": 5}}}
    try:
        result = ab.navigate(config, overrides=[f"{key}={scale}"], threads=1, progress=False)
    except ab.InputError as error:
        one_line(error)
        return
    summary = result.navigation_summary.select_dtypes("number").to_numpy(dtype=float)
    assert not np.isinf(summary).any(), key


@SETTINGS
@given(calls=st.lists(st.tuples(st.sampled_from(["add_pose", "add_range", "add_sample", "finish"]),
                                st.lists(WEIRD, min_size=1, max_size=5)), min_size=1, max_size=8))
def test_the_front_end_takes_any_call_or_refuses_it_in_one_line(calls):
    front_end = ab.FrontEnd({"estimator": {"triggers": ["fixed_window", "pdop_closest_point"]}})
    for name, args in calls:
        try:
            getattr(front_end, name)(*args)
        except ab.InputError as error:
            one_line(error)
        except TypeError as error:  # the wrong number of arguments: Python's own
            assert "argument" in str(error)
    front_end.take_events()


@SETTINGS
@given(n=st.integers(min_value=0, max_value=40), bad=st.sampled_from([None, "nan", "negative", "zero", "inf_pos"]),
       solver=st.sampled_from(["lm_adaptive", "lm_l2", "lm_huber", "ls_double", "ransac", "nope"]))
def test_solve_returns_or_refuses_in_one_line(n, bad, solver):
    p, d = box_samples([2.0, -1.0, 4.0], n=max(n, 1))
    p, d = p[:n], d[:n]
    if n and bad == "nan":
        d[n // 2] = np.nan
    elif n and bad == "negative":
        d[:] = -d
    elif n and bad == "zero":
        d[0] = 0.0
    elif n and bad == "inf_pos":
        p[0, 1] = np.inf
    try:
        result = ab.solve(p, d, solver=solver)
    except ab.InputError as error:
        one_line(error)
        return
    assert bad is None or n == 0
    if result.succeeded:
        assert np.all(np.isfinite(result.p_world_anchor))


@SETTINGS
@given(words=st.lists(st.sampled_from(["tag=1", "tag=x", "time=bag", "time=later", "range=range", "range=data.7",
                                       "anchor=header.seq", "anchor_id=3", "anchor_id=99999999999", "each=nodes",
                                       "field=pose.position", "frame=a", "colour=red", "=", "tag="]),
                      max_size=4),
       kind=st.sampled_from(["--pose", "--range"]), topic=st.sampled_from(["/tag/pose", "/uwb", "/none"]))
def test_the_bag_tool_converts_or_refuses_in_one_line(tmp_path, capsys, words, kind, topic):
    pytest.importorskip("rosbag")
    from anchorbench import bag as converter
    from test_bag import write_bag

    path = tmp_path / "run.bag"
    if not path.exists():
        write_bag(path)
    out = tmp_path / "out"
    status = converter.main([str(path), "--out", str(out), "--overwrite", kind, topic, *words])
    err = capsys.readouterr().err
    assert status in (0, 2), err
    if status == 2:
        assert err.count("\n") == 1 and err.startswith("anchorbench-bag: error: "), err
