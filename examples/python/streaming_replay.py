#!/usr/bin/python3
"""A log replayed through the online front end one row at a time, as a ROS node's callbacks would feed it.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/streaming_replay.py --config configs/tunnel.yaml

Simulates one realization (or reads --poses/--ranges CSVs), then calls add_pose / add_range per
row in time order and prints each event the moment a trigger fires. With --figure, replays the
same log (ab.replay on the DataFrames, with the truth when simulated) and draws the anchors against
the truth and the error against time (ab.plot).
"""

import argparse

import pandas

import anchorbench as ab


def rows_in_time_order(poses, ranges):
    """(t, kind, row) merged by time, poses first at equal times, as the replay reads them."""
    merged = [(t, 0, row) for t, row in zip(poses["t"], poses.itertuples())]
    merged += [(t, 1, row) for t, row in zip(ranges["t"], ranges.itertuples())]
    return sorted(merged, key=lambda item: (item[0], item[1]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--config", default="configs/tunnel.yaml")
    parser.add_argument("--poses")
    parser.add_argument("--ranges")
    parser.add_argument("--figure", help="where to draw the replay's anchors and errors (PNG)")
    args = parser.parse_args()

    truth = None
    if args.poses and args.ranges:
        poses, ranges = pandas.read_csv(args.poses), pandas.read_csv(args.ranges)
    else:
        log = ab.simulate(args.config)
        poses, ranges, truth = log.poses, log.ranges, log.anchors

    front_end = ab.FrontEnd(args.config)
    for t, kind, row in rows_in_time_order(poses, ranges):
        if kind == 0:  # the pose callback
            front_end.add_pose(t, int(row.tag_id), [row.x, row.y, row.z])
        else:          # the range callback
            front_end.add_range(t, int(row.tag_id), int(row.anchor_id), row.range)
            for event in front_end.take_events():
                p = event.solve.p_world_anchor
                print(f"t={event.t_s:7.2f} s  anchor {event.anchor_id:2d}  {event.trigger:20s} "
                      f"{event.solve.status:12s} p=({p[0]:6.2f}, {p[1]:6.2f}, {p[2]:6.2f}) bias={event.solve.bias_m:+.3f}")
    front_end.finish(float(max(poses["t"].max(), ranges["t"].max())))
    for event in front_end.take_events():  # the fixed window fires at the end of the data
        print(f"end          anchor {event.anchor_id:2d}  {event.trigger:20s} {event.solve.status}")

    if args.figure:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        replayed = ab.replay(poses, ranges, anchors=truth, config=args.config)
        fig, (plan, errors) = plt.subplots(1, 2, figsize=(11, 4.5))
        ab.plot.anchors(replayed, truth=truth, ax=plan)
        if truth is not None:
            ab.plot.errors_over_time(replayed, ax=errors)
        fig.tight_layout()
        fig.savefig(args.figure, dpi=110)
        print(f"wrote {args.figure}")


if __name__ == "__main__":
    main()
