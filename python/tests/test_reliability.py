"""Issue 33's Python findings, one test per family: threads, parts, arguments, configs, files."""

import threading

import numpy as np
import pytest

import anchorbench as ab
from conftest import box_samples


def test_several_threads_share_one_front_end():
    """Four threads adding ranges to one FrontEnd (each its own anchor) give the one-thread events."""
    p, d = box_samples([2.0, -1.0, 4.0], n=400)
    t = np.arange(len(d)) * 0.07  # 28 s: every range within the poses kept (FrontEnd.POSE_HISTORY_S)
    tags = np.zeros(len(t), dtype=np.int32)
    config = {"estimator": {"triggers": ["fixed_window", "pdop_closest_point", "certified"]}}

    def feed(front_end, anchor):
        front_end.add_ranges(t, tags, np.full(len(t), anchor, dtype=np.int32), d)

    expected = ab.FrontEnd(config)
    expected.add_poses(t, tags, p)
    for anchor in range(1, 5):
        feed(expected, anchor)
    expected.finish(float(t[-1]))
    key = lambda e: (e.anchor_id, e.trigger, e.t_s, e.n_used, tuple(e.solve.p_world_anchor))
    expected = sorted(map(key, expected.take_events()))
    assert len(expected) >= 8
    for _ in range(3):
        shared = ab.FrontEnd(config)
        shared.add_poses(t, tags, p)
        threads = [threading.Thread(target=feed, args=(shared, anchor)) for anchor in range(1, 5)]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
        shared.finish(float(t[-1]))
        assert sorted(map(key, shared.take_events())) == expected
        assert shared.counters["samples"] == 4 * len(t)


def test_part_names_are_checked_and_built_ins_never_replaced():
    for bad in ["a,b", "a\nb", "", 'q"uote', "a|b"]:
        with pytest.raises(ab.InputError, match="^name: "):
            ab.register_trigger(bad, lambda sample: True)
    with pytest.raises(ab.InputError, match="'lm_adaptive' is a built-in solver"):
        ab.register_solver("lm_adaptive", lambda p, d: (p.mean(axis=0), 0.0, "converged"))
    with pytest.raises(ab.InputError, match="'certified' is a built-in trigger"):
        ab.register_trigger("certified", lambda sample: True)
    with pytest.raises(ab.InputError, match="is a built-in solver"):
        ab.register_solver("nlopt:LN_BOBYQA", lambda p, d: (p.mean(axis=0), 0.0, "converged"))
    # A name of Python's own may be registered again (a notebook cell run twice).
    ab.register_solver("twice", lambda p, d: (p.mean(axis=0), 0.0, "converged"))
    ab.register_solver("twice", lambda p, d: (p.mean(axis=0), 0.0, "converged"))


def _front_end_with_solver(name):
    config = {"estimator": {"triggers": ["fixed_window"], "solver": name, "height_check": {"enabled": False}}}
    front_end = ab.FrontEnd(config)
    p, d = box_samples([2.0, -1.0, 4.0], n=100)
    front_end.add_samples(np.arange(100) * 0.1, np.zeros(100, dtype=np.int32), np.full(100, 3), d, p)
    return front_end


@pytest.mark.parametrize("answer, message", [
    (lambda p, d: (np.full(3, np.nan), 0.0, "converged"), "p_world_anchor .* is not finite"),
    (lambda p, d: (p.mean(axis=0), float("inf"), "converged"), "bias_m is not finite"),
    (lambda p, d: (p.mean(axis=0)[:2], 0.0, "converged"), "p_world_anchor .* wrong type or shape"),
    (lambda p, d: [1, 2], "must return .p_world_anchor, bias_m, status. or a dict"),
    (lambda p, d: {"bias_m": 0.0}, "the dict it returned has no 'p_world_anchor'"),
    (lambda p, d: {"p_world_anchor": p.mean(axis=0), "covariance": np.eye(3)}, "covariance .* wrong type or shape"),
])
def test_a_python_solvers_output_is_checked_and_refused_naming_the_part(answer, message):
    ab.register_solver("checked", answer)
    front_end = _front_end_with_solver("checked")
    with pytest.raises(RuntimeError, match="python solver 'checked': " + message):
        front_end.finish(10.0)


def test_a_failed_solve_may_return_anything_for_its_estimate():
    ab.register_solver("gives_up", lambda p, d: (np.full(3, np.nan), float("nan"), "numerical_failure"))
    front_end = _front_end_with_solver("gives_up")
    front_end.finish(10.0)
    (event,) = front_end.take_events()
    assert event.solve.status == "numerical_failure" and not event.solve.succeeded


@pytest.mark.parametrize("call, message", [
    (lambda: ab.run({}, seed=1.9), "^seed: expected a whole number, got 1.9"),
    (lambda: ab.run({}, seed=-1), "^seed: must be from 0"),
    (lambda: ab.run({}, realizations=1.7), "^realizations: expected a whole number"),
    (lambda: ab.run({}, realizations=True), "^realizations: expected a whole number"),
    (lambda: ab.run({}, threads=-2), "^threads: must be from 0"),
    (lambda: ab.simulate({}, realization=-1), "^realization: must be from 0"),
    (lambda: ab.FrontEnd().add_range(0.0, 0, 2**31, 5.0), "^anchor_id: must be from"),
    (lambda: ab.FrontEnd().add_range(0.0, 0, 1, float("nan")), "^range_m: must be finite"),
    (lambda: ab.FrontEnd().add_pose(0.0, 0, [1.0, 2.0]), r"^p_world_tag: expected shape \(3,\)"),
    (lambda: ab.FrontEnd().add_pose(0.0, 0, "abc"), "^p_world_tag: expected"),
    (lambda: ab.FrontEnd().add_ranges([0.0], [0], [2**31], [5.0]), "^anchor_id: ids must lie within"),
    (lambda: ab.FrontEnd().add_ranges([0.0], [0], [1.5], [5.0]), "^anchor_id: expected whole numbers"),
    (lambda: ab.FrontEnd().add_ranges([0.0, 1.0], [0], [1, 1], [5.0, 5.0]), r"^tag_id: expected an array of shape \(2,\)"),
    (lambda: ab.replay("a\0b.csv", "r.csv"), "^poses: .* holds a NUL byte"),
    (lambda: ab.replay("", "r.csv"), "^poses: an empty path"),
    (lambda: ab.load_config(3), "^config: expected a YAML path, a dict or None"),
    (lambda: ab.run({}, overrides="seed=3"), "^overrides: expected a list"),
    (lambda: ab.solve(np.zeros((50, 3)) + np.arange(50)[:, None], -np.ones(50)), r"^range_m\[0\]: -1 is not a range"),
    (lambda: ab.solve(np.zeros((5, 2)), np.ones(5)), r"^p_world_tag: expected an array of shape \(N, 3\)"),
])
def test_bad_arguments_are_one_input_error_naming_the_argument(call, message):
    with pytest.raises(ab.InputError, match=message) as error:
        call()
    assert "\n" not in str(error.value)


def test_numpy_values_in_a_dict_config_are_plain_values(small_yaml):
    import yaml

    config = yaml.safe_load(small_yaml.read_text())
    config["seed"] = np.int64(5)
    config["scenario"]["ranging"]["sigma_range_m"] = np.float64(0.1)
    config["scenario"]["tag_offsets_m"] = np.zeros((1, 3))
    assert ab.load_config(config).seed == 5
    assert ab.run(config, realizations=1, threads=1, progress=False).text("attempts.csv") == \
        ab.run(small_yaml, realizations=1, threads=1, progress=False).text("attempts.csv")


def test_save_never_replaces_what_the_result_was_made_from(small_yaml, tmp_path):
    folder = tmp_path / "c"
    folder.mkdir()
    (folder / "b.yaml").write_text(small_yaml.read_text())
    (folder / "c.yaml").write_text("base: b.yaml\nrealizations: 1\n")
    result = ab.run(folder / "c.yaml", threads=1, progress=False)
    for target in (folder, tmp_path):
        with pytest.raises(ab.InputError, match="an input of this run"):
            result.save(target, overwrite=True)
    assert (folder / "b.yaml").exists() and (folder / "c.yaml").exists()
    with pytest.raises(ab.InputError, match="^folder: an empty path"):
        result.save("")
    recording = ab.simulate(folder / "c.yaml")
    recording.save(tmp_path / "log")
    replayed = ab.replay(tmp_path / "log" / "poses.csv", tmp_path / "log" / "ranges.csv")
    with pytest.raises(ab.InputError, match="an input of this run"):
        replayed.save(tmp_path / "log", overwrite=True)


def test_progress_reaches_a_callback_up_to_all(small_yaml):
    seen = []
    ab.run(small_yaml, realizations=3, threads=2, progress=lambda done, total: seen.append((done, total)))
    assert seen[-1] == (6, 6)
    assert all(a[0] <= b[0] for a, b in zip(seen, seen[1:]))


def test_an_error_in_the_progress_callback_stops_the_run(small_yaml):
    def fail(done, total):
        raise ValueError("stop here")

    with pytest.raises(ValueError, match="stop here"):
        ab.run(small_yaml, realizations=3, threads=2, progress=fail)
