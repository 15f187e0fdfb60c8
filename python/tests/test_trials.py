"""run, sweep, navigate, explore, pdop_study, replay and simulate from Python: the command line's records as DataFrames, the same bytes when saved."""

import json
import os

import pytest

import anchorbench as ab

SOURCE_DIR = os.environ.get("ANCHORBENCH_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))

SAME_BYTES_RUN = ["attempts.csv", "summary.csv", "summary.md"]  # timing and manifest record the machine and the call


def test_run_gives_the_command_lines_bytes(small_yaml, tmp_path, cli):
    cli("run", small_yaml, "--out", tmp_path / "cli", "--quiet")
    result = ab.run(small_yaml, threads=2)
    result.save(tmp_path / "py")
    for name in SAME_BYTES_RUN:
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    assert set(result.names) == {"attempts.csv", "summary.csv", "summary.md", "timing.csv", "manifest.json"}
    attempts = result.attempts
    assert len(attempts) == 2 * 4 * 4 * 3  # rows x realizations x anchors x the default triggers
    assert set(attempts["method"]) == {"fixed_window", "pdop_closest_point", "certified"}
    assert list(result.summary["method"])[:3] == ["fixed_window", "pdop_closest_point", "certified"]
    assert json.loads(result.text("manifest.json"))["seed"] == 5


def test_a_dict_config_is_the_same_experiment_as_its_file(small_yaml):
    import yaml

    from_file = ab.run(small_yaml, realizations=2, threads=1)
    from_dict = ab.run(yaml.safe_load(small_yaml.read_text()), realizations=2, threads=1)
    assert from_dict.text("attempts.csv") == from_file.text("attempts.csv")


def test_save_refuses_earlier_results_unless_asked(small_yaml, tmp_path):
    result = ab.run(small_yaml, realizations=1, threads=1)
    result.save(tmp_path / "out")
    with pytest.raises(ab.InputError, match=r"add overwrite=True"):
        result.save(tmp_path / "out")
    result.save(tmp_path / "out", overwrite=True)


def test_bad_input_is_the_command_lines_one_line(small_yaml, tmp_path):
    with pytest.raises(ab.InputError) as error:
        ab.load_config(small_yaml, overrides=["scenario.tunnel.width_m=-3"])
    assert str(error.value).startswith(f"{small_yaml}: key 'scenario.tunnel.width_m'")
    with pytest.raises(ab.InputError, match="has moved: write it as estimator.initializer.min_samples"):
        ab.load_config({"estimator": {"trigger": {"min_samples": 30}}})
    with pytest.raises(ab.InputError, match="cannot open the config file"):
        ab.load_config(tmp_path / "missing.yaml")


def test_sweep_gives_a_line_per_point_row_and_trigger(small_yaml, tmp_path, cli):
    axes = {"estimator.trigger.pdop_threshold": "0.5,2"}
    result = ab.sweep(small_yaml, axes, realizations=2, threads=2)
    cli("sweep", small_yaml, "--set", "estimator.trigger.pdop_threshold=0.5,2", "--realizations", 2,
        "--out", tmp_path / "cli", "--quiet")
    assert result.text("sweep.csv") == (tmp_path / "cli" / "sweep.csv").read_text()
    assert len(result.sweep) == 2 * 2 * 3
    assert set(result.sweep["estimator.trigger.pdop_threshold"]) == {0.5, 2.0}


def test_a_parts_own_option_is_listed_and_swept_as_from_the_command_line(small_yaml, tmp_path, cli):
    assert ab.part_options()["travel_span"]["span_m"]["default"] == 10.0
    config = tmp_path / "span.yaml"
    config.write_text(f"base: {small_yaml.name}\nestimator: {{triggers: [pdop_closest_point, travel_span]}}\n")
    result = ab.sweep(config, {"estimator.travel_span.span_m": [2, 40]}, threads=2)
    cli("sweep", config, "--set", "estimator.travel_span.span_m=2,40", "--out", tmp_path / "cli", "--quiet")
    assert result.text("sweep.csv") == (tmp_path / "cli" / "sweep.csv").read_text()
    span = result.sweep[result.sweep["method"] == "travel_span"]
    assert set(span["estimator.travel_span.span_m"]) == {2.0, 40.0}
    with pytest.raises(ab.InputError, match="estimator.travel_span.span_m"):
        ab.sweep(config, {"estimator.travel_span.span_m": [0]})


def test_the_example_environment_is_simulated_as_from_the_command_line(tmp_path, cli):
    assert ab.part_options()["ceiling_grid"]["rows"]["default"] == 3
    config = {"seed": 3, "scenario": {"environment": "ceiling_grid", "ceiling_grid": {"columns": 3},
                                      "trajectory": {"hall_duration_s": 30, "rate_hz": 5}}}
    recording = ab.simulate(config, realization=1)
    assert len(recording.anchors) == 9
    path = tmp_path / "grid.yaml"
    path.write_text("seed: 3\nscenario:\n  environment: ceiling_grid\n  ceiling_grid: {columns: 3}\n"
                    "  trajectory: {hall_duration_s: 30, rate_hz: 5}\n")
    cli("simulate", path, "--realization", 1, "--out", tmp_path / "cli")
    for name in ["poses.csv", "ranges.csv", "anchors.csv"]:
        assert recording.text(name) == (tmp_path / "cli" / name).read_text(), name
    with pytest.raises(ab.InputError, match="scenario.ceiling_grid.rows"):
        ab.simulate({"scenario": {"environment": "ceiling_grid", "ceiling_grid": {"rows": 0}}})


def test_simulate_then_replay_gives_the_command_lines_bytes(small_yaml, tmp_path, cli):
    recording = ab.simulate(small_yaml, realization=1)
    recording.save(tmp_path / "log")
    cli("simulate", small_yaml, "--realization", 1, "--out", tmp_path / "cli_log")
    for name in ["poses.csv", "ranges.csv", "anchors.csv"]:
        assert (tmp_path / "log" / name).read_bytes() == (tmp_path / "cli_log" / name).read_bytes(), name
    log = tmp_path / "log"
    replayed = ab.replay(log / "poses.csv", log / "ranges.csv", anchors=log / "anchors.csv")
    cli("replay", "--poses", log / "poses.csv", "--ranges", log / "ranges.csv", "--anchors", log / "anchors.csv",
        "--out", tmp_path / "cli_replay", "--quiet")
    for name in ["estimates.csv", "replay_summary.json", "replay_summary.md"]:
        assert replayed.text(name) == (tmp_path / "cli_replay" / name).read_text(), name
    assert len(replayed.estimates) == 4 * 3
    assert replayed.estimates["err_m"].notna().any()  # the anchors file gives the truth


def test_replay_refuses_a_malformed_log_naming_its_line(tmp_path):
    (tmp_path / "poses.csv").write_text("t,x,y,z\n0,0,0,0\n1,1,nope,0\n")
    (tmp_path / "ranges.csv").write_text("t,anchor_id,range\n0.5,1,3\n")
    with pytest.raises(ab.InputError, match=r"poses.csv:3"):
        ab.replay(tmp_path / "poses.csv", tmp_path / "ranges.csv")


NAVIGATION_FILES = ["navigation.csv", "navigation_summary.csv", "navigation_error.csv", "navigation.md"]


def test_navigate_gives_the_command_lines_bytes(small_yaml, tmp_path, cli):
    navigated = tmp_path / "navigated.yaml"
    navigated.write_text(small_yaml.read_text() + "navigation: {}\n")
    cli("navigate", navigated, "--realizations", 2, "--out", tmp_path / "cli", "--quiet")
    result = ab.navigate(navigated, realizations=2, threads=2)
    for name in NAVIGATION_FILES:
        assert result.text(name) == (tmp_path / "cli" / name).read_text(), name
    assert set(result.navigation["method"]) == {"fixed_window", "pdop_closest_point", "certified", "true_anchors",
                                                "no_anchors"}
    with pytest.raises(ab.InputError, match="no 'navigation' section"):
        ab.navigate(small_yaml, realizations=1)


def test_explore_and_pdop_study_give_the_command_lines_bytes(tmp_path, cli):
    hall = os.path.join(SOURCE_DIR, "configs", "exploration_uav_hall.yaml")
    cli("explore", hall, "--realizations", 2, "--out", tmp_path / "cli_explore", "--quiet")
    explored = ab.explore(hall, realizations=2, threads=2)
    for name in ["exploration.csv", "exploration_summary.csv", "exploration.md"]:
        assert explored.text(name) == (tmp_path / "cli_explore" / name).read_text(), name
    assert set(explored.exploration["policy"]) >= {"pattern", "guided"}
    study = os.path.join(SOURCE_DIR, "configs", "pdop_study.yaml")
    cli("pdop-study", study, "--realizations", 3, "--every", 20, "--bin-s", 5, "--out", tmp_path / "cli_pdop", "--quiet")
    studied = ab.pdop_study(study, realizations=3, every=20, bin_s=5, threads=2)
    for name in ["pdop_trace.csv", "pdop_study.md"]:
        assert studied.text(name) == (tmp_path / "cli_pdop" / name).read_text(), name
    with pytest.raises(ab.InputError, match=r"^bin_s: must be from 0.01 to 120"):
        ab.pdop_study(study, realizations=1, bin_s=0)
    with pytest.raises(ab.InputError, match="no 'exploration' section|exploration"):
        ab.explore(study, realizations=1)


def test_replay_with_navigate_gives_the_command_lines_navigation_tables(small_yaml, tmp_path, cli):
    ab.simulate(small_yaml).save(tmp_path / "log")
    log = tmp_path / "log"
    (tmp_path / "config.yaml").write_text("realizations: 3\nnavigation: {sigma_range_m: 0.1}\n")
    replayed = ab.replay(log / "poses.csv", log / "ranges.csv", anchors=log / "anchors.csv",
                         config=tmp_path / "config.yaml", navigate=True)
    cli("replay", "--poses", log / "poses.csv", "--ranges", log / "ranges.csv", "--anchors", log / "anchors.csv",
        "--config", tmp_path / "config.yaml", "--navigate", "--out", tmp_path / "cli", "--quiet")
    for name in NAVIGATION_FILES + ["estimates.csv"]:
        assert replayed.text(name) == (tmp_path / "cli" / name).read_text(), name
    assert len(replayed.navigation) == 3 * 5  # draws x (3 triggers, the true anchors, none)


def test_the_oracle_times_each_anchor_where_the_truth_is_known_and_can_be_turned_off(small_yaml):
    table = ab.run(str(small_yaml), realizations=2)
    attempts = table.attempts
    assert {"t_first", "t_oracle", "latency", "t_ideal", "ideal_latency", "blocked_by"} <= set(attempts.columns)
    certifiable = attempts.dropna(subset=["t_oracle"])
    assert len(certifiable) > 0
    assert (certifiable["t_oracle"] >= certifiable["t_first"]).all()
    fired = certifiable[(certifiable["initialized"] == 1) & certifiable["latency"].notna()]
    assert (fired["latency"] > 0).all()
    # The ideal region's time is the anchor's: the same for each of its triggers, and its ratio is
    # to the oracle's time.
    ideal = certifiable.dropna(subset=["t_ideal"])
    assert len(ideal) > 0
    assert (ideal.groupby(["realization", "anchor_id"])["t_ideal"].nunique() == 1).all()
    expected = (ideal["t_ideal"] - ideal["t_first"]) / (ideal["t_oracle"] - ideal["t_first"])
    assert ((ideal["ideal_latency"] - expected).abs() < 1e-9 * expected.abs().clip(lower=1)).all()
    waiting = attempts[(attempts["initialized"] == 0) & (attempts["method"] != "fixed_window")]
    assert waiting["blocked_by"].notna().all()  # every waiting online trigger names its test
    off = ab.run(str(small_yaml), realizations=2, overrides=["estimator.oracle_latency=false"]).attempts
    assert off["t_oracle"].isna().all() and off["latency"].isna().all() and off["t_ideal"].isna().all()
    same = ["row", "realization", "anchor_id", "method", "initialized", "t_init", "err_m"]
    assert off[same].equals(attempts[same])  # the oracle only judges: the attempts are the same
