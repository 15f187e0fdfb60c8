"""anchorbench-bag: a ROS 1 bag's poses and UWB ranges as the replay CSVs (docs/python.md, "ROS bags").

    anchorbench-bag run.bag --out log/ --pose-topic /odom --range-topic /uwb/range

writes log/poses.csv (t,tag_id,x,y,z) and log/ranges.csv (t,tag_id,anchor_id,range) for
``anchorbench replay --poses log/poses.csv --ranges log/ranges.csv``. Message types are read
from the bag; presets cover geometry_msgs/PoseStamped, geometry_msgs/TransformStamped and
nav_msgs/Odometry for poses, and sensor_msgs/Range for ranges (the anchor id is the number the
frame_id ends in). Any other message is read through field paths: ``--range-field``,
``--anchor-field`` (dots, and numbers for list items: ``data.1``), with ``--each`` naming a list
of measurements in one message. Times are the header stamps (``--time bag`` for the time the bag
recorded). Reads with Debian's python3-rosbag; ROS 2 bags are not read (docs/python.md says why).
Bad input is one line on stderr and exit 2; the output folder appears whole or not at all.
"""

from __future__ import annotations

import argparse
import csv
import os
import re
import shutil
import sys
import tempfile

POSE_PRESETS = {  # message type -> the field path of its position
    "geometry_msgs/PoseStamped": "pose.position",
    "geometry_msgs/PoseWithCovarianceStamped": "pose.pose.position",
    "geometry_msgs/TransformStamped": "transform.translation",
    "geometry_msgs/PointStamped": "point",
    "nav_msgs/Odometry": "pose.pose.position",
}
RANGE_PRESETS = {  # message type -> (range field, anchor field); None: the number frame_id ends in
    "sensor_msgs/Range": ("range", None),
}


class BagError(Exception):
    """Bad input: one line for the user."""


def field(message, path: str, what: str):
    """The value at a dotted path (a number indexes a list)."""
    value = message
    for part in path.split("."):
        try:
            value = value[int(part)] if part.isdigit() else getattr(value, part)
        except (AttributeError, IndexError, TypeError):
            raise BagError(f"{what}: no field '{path}' in {type(message).__name__} (at '{part}')") from None
    return value


def anchor_of_frame(frame_id: str, what: str) -> int:
    found = re.search(r"(\d+)\s*$", frame_id)
    if not found:
        raise BagError(f"{what}: frame_id '{frame_id}' ends in no anchor number; give --anchor-field")
    return int(found.group(1))


def stamp(message, recorded, time: str, what: str) -> float:
    if time == "bag":
        return recorded.to_sec()
    header = getattr(message, "header", None)
    if header is None:
        raise BagError(f"{what}: {type(message).__name__} has no header; use --time bag")
    return header.stamp.to_sec()


def topic_type(bag, topic: str, what: str) -> str:
    info = bag.get_type_and_topic_info().topics
    if topic not in info:
        raise BagError(f"{what} {topic}: not in the bag (its topics: {', '.join(sorted(info)) or 'none'})")
    return info[topic].msg_type


def pose_rows(bag, args):
    what = "--pose-topic"
    kind = topic_type(bag, args.pose_topic, what)
    path = args.position_field or POSE_PRESETS.get(kind)
    if path is None:
        raise BagError(f"{what} {args.pose_topic}: {kind} has no preset; give --position-field")
    for _, message, recorded in bag.read_messages(topics=[args.pose_topic]):
        p = field(message, path, what)
        yield stamp(message, recorded, args.time, what), args.tag_id, float(p.x), float(p.y), float(p.z)


def range_rows(bag, args):
    what = "--range-topic"
    kind = topic_type(bag, args.range_topic, what)
    preset_range, preset_anchor = RANGE_PRESETS.get(kind, (None, None))
    range_field = args.range_field or preset_range
    if range_field is None:
        raise BagError(f"{what} {args.range_topic}: {kind} has no preset; give --range-field and --anchor-field")
    for _, message, recorded in bag.read_messages(topics=[args.range_topic]):
        t = stamp(message, recorded, args.time, what)
        for item in (field(message, args.each, what) if args.each else [message]):
            if args.anchor_field:
                anchor = int(field(item, args.anchor_field, what))
            elif preset_anchor is None and kind in RANGE_PRESETS:
                anchor = anchor_of_frame(message.header.frame_id, what)
            else:
                raise BagError(f"{what} {args.range_topic}: give --anchor-field for {kind}")
            yield t, args.tag_id, anchor, float(field(item, range_field, what))


def write(folder: str, name: str, header, rows) -> int:
    count = 0
    with open(os.path.join(folder, name), "w", newline="") as out:
        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(header)
        for row in rows:
            writer.writerow([repr(v) if isinstance(v, float) else v for v in row])
            count += 1
    return count


def convert(args) -> str:
    import rosbag  # Debian's python3-rosbag

    out = os.path.abspath(args.out)
    if os.path.exists(out) and not args.overwrite:
        raise BagError(f"{args.out}: exists; add --overwrite to replace it")
    if not os.path.isfile(args.bag):
        raise BagError(f"{args.bag}: no such bag file")
    parent = os.path.dirname(out)
    os.makedirs(parent, exist_ok=True)
    partial = tempfile.mkdtemp(prefix=f".{os.path.basename(out)}.partial-", dir=parent)
    try:
        try:
            bag = rosbag.Bag(args.bag)
        except Exception as error:  # rosbag raises its own ROSBagException and others
            raise BagError(f"{args.bag}: not a readable ROS 1 bag: {error}") from None
        with bag:
            poses = write(partial, "poses.csv", ["t", "tag_id", "x", "y", "z"], pose_rows(bag, args))
            ranges = write(partial, "ranges.csv", ["t", "tag_id", "anchor_id", "range"], range_rows(bag, args))
        if poses == 0 or ranges == 0:
            raise BagError(f"{args.bag}: {poses} poses and {ranges} ranges on the topics: nothing to replay")
        if os.path.exists(out):
            shutil.rmtree(out)
        os.rename(partial, out)
    except BaseException:
        shutil.rmtree(partial, ignore_errors=True)
        raise
    return f"anchorbench-bag: {poses} poses, {ranges} ranges -> {args.out}"


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="anchorbench-bag", description=__doc__.split("\n\n")[0])
    p.add_argument("bag")
    p.add_argument("--out", required=True, help="the folder of poses.csv and ranges.csv")
    p.add_argument("--pose-topic", required=True)
    p.add_argument("--range-topic", required=True)
    p.add_argument("--position-field", help="field path of the position (a message without a preset)")
    p.add_argument("--range-field", help="field path of the range, m")
    p.add_argument("--anchor-field", help="field path of the anchor id")
    p.add_argument("--each", help="field path of a list of measurements in one message")
    p.add_argument("--tag-id", type=int, default=0, help="the tag these poses and ranges are of (default 0)")
    p.add_argument("--time", choices=["header", "bag"], default="header")
    p.add_argument("--overwrite", action="store_true")
    return p


def main(argv=None) -> int:
    args = parser().parse_args(argv)
    try:
        print(convert(args))
    except BagError as error:
        print(f"anchorbench-bag: error: {error}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
