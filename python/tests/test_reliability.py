"""Issue 33's Python findings, one test per family: threads, parts, arguments, configs, files."""

import threading

import numpy as np
import pytest

import anchorbench as ab
from conftest import box_samples


def test_several_threads_share_one_front_end():
    """Four threads adding ranges to one FrontEnd (each its own anchor) give the one-thread events."""
    p, d = box_samples([2.0, -1.0, 4.0], n=400)
    t = np.arange(len(d)) * 0.1
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
