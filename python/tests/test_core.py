"""The core on arrays: solvers, PDOPs, and the online front end fed one sample at a time or in batches."""

import numpy as np
import pytest

import anchorbench as ab
from conftest import box_samples


def test_solve_finds_an_anchor_and_its_bias():
    p, d = box_samples([2.0, -1.0, 4.0])
    result = ab.solve(p, d)
    assert result.succeeded, result
    assert np.linalg.norm(result.p_world_anchor - [2.0, -1.0, 4.0]) < 0.1
    assert abs(result.bias_m - 0.3) < 0.05
    assert result.covariance.shape == (4, 4)
    assert ab.solve(p, d, solver="ls_double").succeeded
    assert ab.solve(p, d, config={"estimator": {"nls": {"kernel": "fixed", "fixed_alpha": 2}}}).alpha == 2.0


def test_solve_refuses_a_wrong_shape_and_an_unknown_solver():
    p, d = box_samples([2.0, -1.0, 4.0])
    with pytest.raises(ValueError, match=r"p_world_tag: expected an array of shape \(N, 3\)"):
        ab.solve(p[:, :2], d)
    with pytest.raises(ValueError, match=r"range_m: expected an array of shape \(400,\)"):
        ab.solve(p, d[:-1])
    with pytest.raises(ab.InputError, match="unknown solver 'no_such'"):
        ab.solve(p, d, solver="no_such")


def test_pdops_on_arrays():
    p, d = box_samples([2.0, -1.0, 4.0])
    assert 0 < ab.closest_point_pdop(p, d) < np.inf
    assert 0 < ab.geometry_pdop(p, d, np.array([2.0, -1.0, 4.0])) < 10
    line = np.column_stack([np.linspace(0, 10, 50), np.zeros(50), np.zeros(50)])
    assert ab.closest_point_pdop(line, np.linspace(5, 6, 50)) == np.inf  # a straight line cannot place an anchor


def _feed_one_by_one(front_end, t, p, d):
    for i in range(len(t)):
        front_end.add_sample(float(t[i]), 0, 7, float(d[i]), p[i])


def test_the_front_end_gives_the_same_events_one_sample_at_a_time_and_in_a_batch():
    p, d = box_samples([2.0, -1.0, 4.0], n=600)
    t = np.arange(len(d)) * 0.1
    config = {"estimator": {"triggers": ["fixed_window", "pdop_closest_point"]}}
    single, batch = ab.FrontEnd(config), ab.FrontEnd(config)
    _feed_one_by_one(single, t, p, d)
    batch.add_samples(t, np.zeros(len(t), dtype=np.int32), np.full(len(t), 7, dtype=np.int32), d, p)
    for front_end in (single, batch):
        front_end.finish(float(t[-1]))
    events_single, events_batch = single.take_events(), batch.take_events_array()
    assert [e.trigger for e in events_single] == ["pdop_closest_point", "fixed_window"]
    assert len(events_batch) == 2
    for event, record in zip(events_single, events_batch):
        assert event.anchor_id == record["anchor_id"] == 7
        assert event.t_s == record["t_s"] and event.n_used == record["n_used"]
        assert np.array_equal(event.solve.p_world_anchor, [record["x"], record["y"], record["z"]])
        assert record["status"].decode() == event.solve.status
    assert single.triggers == ["fixed_window", "pdop_closest_point"]
    assert single.counters["samples"] == 600


def test_poses_and_ranges_meet_in_the_front_end():
    p, d = box_samples([2.0, -1.0, 4.0], n=300)
    t = np.arange(len(d)) * 0.1
    front_end = ab.FrontEnd({"estimator": {"triggers": ["fixed_window"]}})
    front_end.add_poses(t, np.zeros(len(t), dtype=np.int32), p)
    front_end.add_ranges(t, np.zeros(len(t), dtype=np.int32), np.full(len(t), 3, dtype=np.int32), d)
    front_end.finish(float(t[-1]))
    (event,) = front_end.take_events()
    assert event.anchor_id == 3 and event.solve.succeeded
    assert np.linalg.norm(event.solve.p_world_anchor - [2.0, -1.0, 4.0]) < 0.2


def test_why_not_says_which_test_holds_each_waiting_anchor_back():
    p, d = box_samples([2.0, -1.0, 4.0], n=600)
    t = np.arange(len(d)) * 0.1
    front_end = ab.FrontEnd({"estimator": {"triggers": ["pdop_closest_point", "certified"]}})
    n = 25  # a few samples: nothing certified yet
    front_end.add_samples(t[:n], np.zeros(n, dtype=np.int32), np.full(n, 7, dtype=np.int32), d[:n], p[:n])
    waiting = {w["trigger"]: w for w in front_end.why_not()}
    assert set(waiting) == {"pdop_closest_point", "certified"}
    assert waiting["pdop_closest_point"]["blocked_by"] in ("samples", "pdop")
    certified = waiting["certified"]
    assert certified["anchor_id"] == 7 and certified["blocked_by"]
    assert certified["value"] is None or certified["limit"] is not None
    if certified["blocked_by"] == "region":
        shares = [certified[k] for k in certified if k.startswith("share_")]
        assert abs(sum(shares) - 1.0) < 1e-9
    front_end.add_samples(t[n:], np.zeros(len(t) - n, dtype=np.int32), np.full(len(t) - n, 7, dtype=np.int32), d[n:],
                          p[n:])
    fired = {e.trigger for e in front_end.take_events()}
    assert {w["trigger"] for w in front_end.why_not()}.isdisjoint(fired)  # nothing holds a fired trigger back


def test_a_mirror_refusal_says_what_more_data_would_settle_it():
    # A ground robot's loop, the tags within 3 mm of a plane: the whole-log fit's mirror through
    # that plane fits as well, so the fit is refused, and more of the same would not settle it.
    k = np.arange(400)
    p = np.column_stack([3.0 * np.cos(0.05 * k), 2.0 * np.sin(0.05 * k), 1.5 + 0.003 * np.sin(0.9 * k)])
    d = np.linalg.norm(p - [1.0, 1.0, 3.5], axis=1) + 0.1 + np.random.default_rng(3).normal(0.0, 0.05, len(k))
    front_end = ab.FrontEnd({"estimator": {"triggers": ["fixed_window"]}})
    front_end.add_samples(0.1 * k, np.zeros(len(k), dtype=np.int32), np.full(len(k), 2, dtype=np.int32), d, p)
    front_end.finish(0.1 * k[-1])
    (refused,) = front_end.take_events()
    assert refused.solve.status == "height_unobservable"
    (why,) = front_end.why_not()
    assert why["blocked_by"] == "mirror" and why["limit"] == 9.21 and why["value"] < why["limit"]
    assert why["samples_needed"] > 10 * len(k)  # not soon, or never (inf)
    assert why["evidence_explained"] == 0.0  # the mirror check itself allows no model error


def test_guide_ranks_where_to_range_from_for_a_waiting_anchor():
    # A robot's loop on the floor beside an anchor 0.2 m above it: its height is barely seen, so
    # the certificate waits, and ranging from above the floor is what would close its region.
    t = np.arange(600) * 0.1
    p = np.stack([3 + 5 * np.cos(0.2 * t), 4 + 4 * np.sin(0.13 * t), 0.5 + 0.02 * np.sin(0.7 * t)], axis=1)
    anchor = np.array([15.0, 4.0, 0.7])
    d = np.linalg.norm(p - anchor, axis=1) + 0.1 + 0.05 * np.random.default_rng(3).standard_normal(len(t))
    front_end = ab.FrontEnd({"estimator": {"triggers": ["pdop_closest_point", "certified"]}})
    assert front_end.guide() == []  # nothing judged yet
    front_end.add_samples(t, np.zeros(len(t), dtype=np.int32), np.full(len(t), 7, dtype=np.int32), d, p)
    guided = front_end.guide(range_rate_hz=20.0)
    assert [(g["anchor_id"], g["trigger"]) for g in guided] == [(7, "certified")]
    g = guided[0]
    assert len(g["best"]) == 5 and g["region_m"] > g["accuracy_m"]
    assert g["blocked_by"] == {w["trigger"]: w for w in front_end.why_not()}["certified"]["blocked_by"]
    regions = [c["region_m"] for c in g["best"]]
    assert regions == sorted(regions) and regions[0] < g["region_m"]
    assert all(np.abs(c["p_world_candidate"] - p[-1]).max() <= 2.0 + 1e-9 for c in g["best"])
    assert g["seconds_to_certify"] == pytest.approx(min(c["samples_to_certify"] for c in g["best"]) / 20.0)
    # Candidates of the caller's: above the floor ranks first.
    floor, above = [9.0, 4.0, 0.5], [9.0, 4.0, 2.5]
    ranked = front_end.guide(candidates=np.array([floor, above]), best=2)[0]["best"]
    assert list(ranked[0]["p_world_candidate"]) == above
    assert ranked[0]["region_m"] < ranked[1]["region_m"]


def test_each_alternative_is_judged_with_the_tags_offsets_that_suit_it():
    """The cone approach's radio row, realization 74: three tags whose links to an anchor 4.6 m away
    differ by 0.2-0.3 m, seen from 0.4 m of path in the first seconds. Judged with the offsets of the
    tags that the estimate fitted for itself, the true anchor fitted worse than a point 5.6 m off,
    and the certificate took that point at 1.6 s; with each fit's own offsets it waits."""
    from pathlib import Path
    config = Path(__file__).resolve().parents[2] / "configs" / "cone_approach.yaml"
    log = ab.simulate(config, realization=74,
                      overrides=["scenario.ranging.antenna_bias_m=0.06", "scenario.ranging.link_offset_m=0.15"])
    replayed = ab.replay(log.poses, log.ranges, anchors=log.anchors,
                         config={"base": str(config), "estimator": {"triggers": ["certified"]}})
    done = replayed.estimates[replayed.estimates["initialized"] == 1]
    assert len(done) == 4  # every anchor, in time
    assert done["err_m"].max() < 0.75
