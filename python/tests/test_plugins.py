"""Solvers and triggers written in Python, run by the Monte Carlo engine and by replay beside the built-ins."""

import numpy as np
import pytest

import anchorbench as ab
from conftest import box_samples


def gauss_newton(p_world_tag, range_m):
    """A plain Gauss-Newton on (p_A, gamma) from the tags' centroid raised by 1 m: a numpy solver."""
    x = np.append(p_world_tag.mean(axis=0) + [0.0, 0.0, 1.0], 0.0)
    for _ in range(30):
        diff = x[:3] - p_world_tag
        dist = np.linalg.norm(diff, axis=1)
        residual = range_m - (dist + x[3])
        jacobian = np.column_stack([diff / dist[:, None], np.ones(len(dist))])
        step, *_ = np.linalg.lstsq(jacobian, residual, rcond=None)
        x += step
        if np.linalg.norm(step) < 1e-9:
            break
    return x[:3], float(x[3]), "converged"


ab.register_solver("py_gauss_newton", gauss_newton, "Gauss-Newton in numpy (the tests')")


def test_a_python_solver_solves_through_the_core():
    p, d = box_samples([2.0, -1.0, 4.0])
    result = ab.solve(p, d, solver="py_gauss_newton")
    assert result.status == "converged"
    assert np.linalg.norm(result.p_world_anchor - [2.0, -1.0, 4.0]) < 0.1
    assert ("py_gauss_newton", "Gauss-Newton in numpy (the tests')") in ab.parts()["solvers"]


def test_the_engine_runs_a_python_solver_beside_a_builtin_on_the_same_trials(small_yaml):
    ours = ab.run(small_yaml, overrides=["estimator.solver=py_gauss_newton"], realizations=2, threads=2)
    builtin = ab.run(small_yaml, overrides=["estimator.solver=lm_adaptive"], realizations=2, threads=2)
    assert len(ours.attempts) == len(builtin.attempts)
    # The same trials: each attempt's trigger time and data are the builtin's wherever neither refused.
    fixed = lambda result: result.attempts.query("method == 'fixed_window'").reset_index(drop=True)
    assert (fixed(ours)["n_used"] == fixed(builtin)["n_used"]).all()
    assert fixed(ours)["err_m"].median() < 0.5
    again = ab.run(small_yaml, overrides=["estimator.solver=py_gauss_newton"], realizations=2, threads=1)
    assert again.text("attempts.csv") == ours.text("attempts.csv")  # any thread count, the same bytes


def test_an_error_in_a_python_part_names_it():
    def broken(p_world_tag, range_m):
        raise ZeroDivisionError("on purpose")

    ab.register_solver("py_broken", broken)
    p, d = box_samples([2.0, -1.0, 4.0])
    with pytest.raises(RuntimeError, match="python solver 'py_broken': ZeroDivisionError: on purpose"):
        ab.solve(p, d, solver="py_broken")


def test_a_python_trigger_decides_when_the_anchor_is_solved():
    ab.register_trigger("py_after_200", lambda sample: sample["eligible"] and sample["n_admitted"] >= 200)
    p, d = box_samples([2.0, -1.0, 4.0], n=500)
    t = np.arange(len(d)) * 0.1
    front_end = ab.FrontEnd({"estimator": {"triggers": ["py_after_200"]}})
    front_end.add_samples(t, np.zeros(len(t), dtype=np.int32), np.zeros(len(t), dtype=np.int32), d, p)
    (event,) = front_end.take_events()
    assert event.trigger == "py_after_200" and event.n_used == 200


def test_replay_runs_a_python_solver_on_a_recorded_log(small_yaml, tmp_path):
    ab.simulate(small_yaml).save(tmp_path / "log")
    log = tmp_path / "log"
    calls = []

    def counted(p_world_tag, range_m):
        calls.append(len(range_m))
        return gauss_newton(p_world_tag, range_m)

    ab.register_solver("py_counted", counted)
    config = {"estimator": {"solver": "py_counted", "triggers": ["fixed_window", "pdop_closest_point"]}}
    replayed = ab.replay(log / "poses.csv", log / "ranges.csv", anchors=log / "anchors.csv", config=config)
    assert len(calls) >= 4  # at least one solve an anchor
    fixed = replayed.estimates.query("method == 'fixed_window' and status == 'converged'")
    assert len(fixed) >= 1 and fixed["err_m"].max() < 1.0  # the mirror check may refuse the others
