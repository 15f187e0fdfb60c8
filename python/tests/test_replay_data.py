"""ab.replay on data in memory, with every option of the command line; what it says about the log
(summary, drops, warnings, traces); events as DataFrames; results that depend only on the data used."""

import warnings

import numpy as np
import pytest

import anchorbench as ab


@pytest.fixture
def log(small_yaml):
    return ab.simulate(small_yaml, realization=1)


def test_dataframes_replay_as_their_files_do(log, tmp_path):
    log.save(tmp_path / "log")
    from_files = ab.replay(tmp_path / "log" / "poses.csv", tmp_path / "log" / "ranges.csv",
                           anchors=tmp_path / "log" / "anchors.csv")
    from_frames = ab.replay(log.poses, log.ranges, anchors=log.anchors)
    assert from_frames.text("estimates.csv") == from_files.text("estimates.csv")
    as_columns = ab.replay({c: log.poses[c].to_numpy() for c in log.poses}, [log.ranges.iloc[::2], log.ranges.iloc[1::2]])
    assert list(as_columns.estimates["x"]) == pytest.approx(list(ab.replay(log.poses, log.ranges).estimates["x"]),
                                                           nan_ok=True)


def test_every_command_line_option_reaches_the_replay(log, cli, tmp_path):
    log.save(tmp_path / "log")
    options = dict(max_range_m=6.0, average_poses_within_m=0.01, sort_window_s=0.5, max_speed_mps=20.0)
    replayed = ab.replay(log.poses, log.ranges, warn=False, **options)
    policy = replayed.replay_summary["policy"]
    for key, value in options.items():
        assert policy[key if key != "average_poses_within_m" else "average_within_m"] == value
    done = cli("replay", "--poses", tmp_path / "log" / "poses.csv", "--ranges", tmp_path / "log" / "ranges.csv",
               "--max-range-m", 6, "--average-poses-within-m", 0.01, "--sort-window-s", 0.5, "--max-speed-mps", 20,
               "--out", tmp_path / "cli")
    assert replayed.text("estimates.csv") == (tmp_path / "cli" / "estimates.csv").read_text()
    # The command line's drop summary on stderr is the result's warning, word for word (a DataFrame
    # named as its argument where the command line names the file).
    assert [w.replace("ranges (DataFrame)", str(tmp_path / "log" / "ranges.csv")) for w in replayed.warnings] == \
        [done.stderr.strip()]
    with pytest.raises(ab.InputError, match="max_range_m"):
        ab.replay(log.poses, log.ranges, max_range_m=-1)
    with pytest.raises(ab.InputError, match="out_of_order"):
        ab.replay(log.poses, log.ranges, out_of_order="shuffle")


def test_dropped_rows_are_a_warning_a_dict_and_a_dataframe(log):
    with pytest.warns(ab.ReplayWarning, match=r"range_beyond_max: \d+ \(e.g. ranges \(DataFrame\):2\)"):
        replayed = ab.replay(log.poses, log.ranges, max_range_m=6.0)
    drops = replayed.drops
    assert set(drops["kind"]) == {"ranges"} and set(drops["reason"]) == {"range_beyond_max"}
    assert replayed.replay_summary["ranges"] == ["ranges (DataFrame)"]
    assert drops["count"].sum() == replayed.replay_summary["dropped"] > 0
    summary = replayed.summary
    assert list(summary["method"]) == ["fixed_window", "pdop_closest_point", "certified"]
    assert set(summary["dropped_rows"]) == {replayed.replay_summary["dropped"]}
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        clean = ab.replay(log.poses, log.ranges)  # nothing dropped: no warning
    assert clean.warnings == [] and len(clean.drops) == 0
    with pytest.raises(ab.InputError, match=r"^poses \(DataFrame\):2: column 'x'"):  # line 2: row 0
        ab.replay(log.poses.assign(x="nope"), log.ranges)


def test_strict_refuses_what_would_be_dropped(log):
    with pytest.raises(ab.InputError, match=r"^ranges \(DataFrame\):2: .* beyond max_range_m 6 \(strict=True\)"):
        ab.replay(log.poses, log.ranges, max_range_m=6.0, strict=True)


def test_traces_as_the_command_line_writes_them(log, cli, tmp_path):
    log.save(tmp_path / "log")
    replayed = ab.replay(log.poses, log.ranges, trace=True, certificate_trace=True)
    cli("replay", "--poses", tmp_path / "log" / "poses.csv", "--ranges", tmp_path / "log" / "ranges.csv",
        "--trace", tmp_path / "trace.csv", "--certificate-trace", tmp_path / "certificate.csv", "--quiet")
    assert replayed.text("trace.csv") == (tmp_path / "trace.csv").read_text()
    assert replayed.text("certificate_trace.csv") == (tmp_path / "certificate.csv").read_text()
    assert len(replayed.trace) == len(log.ranges)
    assert set(replayed.certificate_trace["method"]) == {"certified"}


def test_a_tag_without_poses_moves_no_other_anchors_time(log):
    """Ranges of a tag that has no poses are dropped; they change nothing else, the fixed window's
    t_init included (it is its anchor's own last sample, not the end of all data)."""
    unrelated = log.ranges.copy()
    unrelated["tag_id"] = 9
    unrelated["t"] = unrelated["t"] + 5.0  # later than any pose of tag 0
    alone = ab.replay(log.poses, log.ranges)
    with pytest.warns(ab.ReplayWarning):
        beside = ab.replay(log.poses, [log.ranges, unrelated])
    assert beside.text("estimates.csv") == alone.text("estimates.csv")
    fixed = alone.estimates[alone.estimates["method"] == "fixed_window"]
    last = log.ranges.groupby("anchor_id")["t"].max()
    assert (fixed.set_index("anchor_id")["t_init"] <= last.reindex(fixed["anchor_id"]).to_numpy()).all()


def log_arrays(log, ranges=slice(None)):
    p, r = log.poses, log.ranges.iloc[ranges]
    return (p["t"].to_numpy(), p["tag_id"].to_numpy(), p[["x", "y", "z"]].to_numpy(), r["t"].to_numpy(),
            r["tag_id"].to_numpy(), r["anchor_id"].to_numpy(), r["range"].to_numpy())


def test_whole_log_arrays_lose_no_range_silently(log):
    """All poses, then all ranges: those before the poses kept are dropped, and said so once; add_log
    places every one."""
    pt, ptag, p, rt, rtag, anchors, d = log_arrays(log)
    assert rt[-1] - rt[0] > ab.FrontEnd.POSE_HISTORY_S  # the log is longer than the poses kept
    naive = ab.FrontEnd()
    naive.add_poses(pt, ptag, p)
    with pytest.warns(ab.FrontEndWarning, match=r"\d+ range\(s\) could not be placed.*add_log"):
        naive.add_ranges(rt, rtag, anchors, d)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        naive.add_ranges(rt[-1:], rtag[-1:], anchors[-1:], d[-1:])  # once
    whole = ab.FrontEnd()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        whole.add_log(pt, ptag, p, rt, rtag, anchors, d)
        whole.finish(rt[-1])
    assert whole.counters["samples"] == len(rt)
    assert whole.counters["ranges_outside_poses"] == 0
    with pytest.raises(ab.InputError, match="range_t_s: expected times in increasing order"):
        ab.FrontEnd().add_log(pt, ptag, p, rt[::-1], rtag, anchors, d)


def test_events_and_waits_as_dataframes(log):
    front_end = ab.FrontEnd({"estimator": {"triggers": ["pdop_closest_point", "certified"]}})
    front_end.add_log(*log_arrays(log))
    waiting = front_end.why_not_frame()  # this short log leaves most anchors waiting
    assert {"anchor_id", "trigger", "blocked_by", "value", "limit"} <= set(waiting.columns)
    assert set(waiting["trigger"]) <= {"pdop_closest_point", "certified"} and len(waiting)
    assert set(waiting["blocked_by"]) <= {"pdop", "region", "region_ends", "height_prior", "alternative", "mirror", "stability",
                                          "doubling", "samples", "retry", "solve"}
    events = front_end.take_events_frame()
    assert len(events) and set(events["trigger"]) <= {"pdop_closest_point", "certified"}
    assert all(isinstance(s, str) for s in events["status"]) and "converged" in set(events["status"])
    assert np.isfinite(events[["x", "y", "z"]].to_numpy()).all()


def test_plots_draw_every_initialized_anchor_and_refuse_errors_without_truth(log):
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.patches import Circle

    replayed = ab.replay(log.poses, log.ranges, anchors=log.anchors)
    done = replayed.estimates[replayed.estimates["initialized"] == 1]
    ax = ab.plot.anchors(replayed, truth=log.anchors)
    assert sum(isinstance(p, Circle) for p in ax.patches) == done["radius99_m"].notna().sum() > 0
    ax = ab.plot.errors_over_time(replayed)
    assert sum(len(c.get_offsets()) for c in ax.collections) == len(done)
    with pytest.raises(ValueError, match="no truth"):
        ab.plot.errors_over_time(ab.replay(log.poses, log.ranges))
