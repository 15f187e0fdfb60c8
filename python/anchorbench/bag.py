"""anchorbench-bag: ROS 1 bags' poses and UWB ranges as the replay CSVs (docs/python.md, "ROS bags").

    anchorbench-bag run.bag --out log/ --pose /mocap/tag1 tag=1 --range /uwb/tag1 tag=1

writes log/poses.csv (t,tag_id,x,y,z) and log/ranges.csv (t,tag_id,anchor_id,range), each in time
order over every topic, for ``anchorbench replay --poses log/poses.csv --ranges log/ranges.csv``.
``--pose TOPIC [key=value ...]`` and ``--range TOPIC [key=value ...]`` repeat, one per topic, each
with its own tag and settings; topics may come from several bags. Without a pose topic only
ranges.csv is written (poses from elsewhere), and the other way round.

Keys of a topic (the presets fill them from the message type the bag records):
  tag=N          the tag the topic is of (default 0)
  time=header|bag  the header stamp, or when the bag recorded the message (default: header where
                 the message has one)
  field=PATH     a pose topic's position (e.g. pose.position)
  frame=NAME     a tf topic's child_frame_id to read (tf2_msgs/TFMessage)
  range=PATH     a range topic's range, m
  anchor=PATH    a range topic's anchor id; or anchor_id=N, one anchor for the whole topic
  each=PATH      a list of measurements in one message (e.g. nodes), each read with range/anchor

Paths are dotted; a number indexes a list (``data.1``). The single-tag flags of earlier versions
(--pose-topic, --range-topic, --tag-id, --position-field, --range-field, --anchor-field, --each,
--time) still work and set the defaults of every topic. Reads with Debian's python3-rosbag; ROS 2
bags are not read (docs/python.md says why). Bad input is one line on stderr and exit 2; the output
folder appears whole or not at all, and never replaces a folder that holds a bag it reads.
"""

from __future__ import annotations

import argparse
import csv
import os
import re
import shutil
import sys
import tempfile
from dataclasses import dataclass, replace
from typing import Dict, Iterator, List, Optional, Tuple

# message type -> the keys it presets (the bag records the type's real ROS name)
POSE_PRESETS: Dict[str, Dict[str, str]] = {
    "geometry_msgs/PoseStamped": {"field": "pose.position"},
    "geometry_msgs/PoseWithCovarianceStamped": {"field": "pose.pose.position"},
    "geometry_msgs/TransformStamped": {"field": "transform.translation"},
    "geometry_msgs/PointStamped": {"field": "point"},
    "nav_msgs/Odometry": {"field": "pose.pose.position"},
    "tf2_msgs/TFMessage": {"each": "transforms", "field": "transform.translation"},
}
RANGE_PRESETS: Dict[str, Dict[str, str]] = {
    "sensor_msgs/Range": {"range": "range"},  # the anchor: the number its frame_id ends in
    # Nooploop LinkTrack (nlink_parser): one tag's ranges to every anchor in nodes[], no header.
    "nlink_parser/LinktrackNodeframe2": {"each": "nodes", "range": "dis", "anchor": "id", "time": "bag"},
    "nlink_parser/LinktrackNodeframe3": {"each": "nodes", "range": "dis", "anchor": "id", "time": "bag"},
}
POSE_KEYS = {"tag", "time", "field", "frame", "each"}
RANGE_KEYS = {"tag", "time", "range", "anchor", "anchor_id", "each"}
MAX_ID = 2**31 - 1


class BagError(Exception):
    """Bad input: one line for the user."""


@dataclass(frozen=True)
class Topic:
    kind: str  # "pose" or "range"
    name: str
    tag: int = 0
    time: Optional[str] = None
    field: Optional[str] = None
    frame: Optional[str] = None
    range: Optional[str] = None
    anchor: Optional[str] = None
    anchor_id: Optional[int] = None
    each: Optional[str] = None

    @property
    def what(self) -> str:
        return f"--{self.kind} {self.name}"


def whole(text: str, what: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise BagError(f"{what}: '{text}' is not a whole number") from None
    if not -MAX_ID - 1 <= value <= MAX_ID:
        raise BagError(f"{what}: {value} is beyond the ids anchorbench reads ([{-MAX_ID - 1}, {MAX_ID}])")
    return value


def parse_topic(kind: str, words: List[str], defaults: dict) -> Topic:
    name, settings = words[0], dict(defaults)
    allowed = POSE_KEYS if kind == "pose" else RANGE_KEYS
    for word in words[1:]:
        key, equals, value = word.partition("=")
        if not equals or key not in allowed or not value:
            raise BagError(f"--{kind} {name}: '{word}' is not one of {', '.join(sorted(k + '=...' for k in allowed))}")
        settings[key] = value
    if settings.get("time") not in (None, "header", "bag"):
        raise BagError(f"--{kind} {name}: time={settings['time']}: choose header or bag")
    what = f"--{kind} {name}"
    settings["tag"] = whole(str(settings.get("tag", 0)), f"{what} tag")
    if settings.get("anchor_id") is not None:
        settings["anchor_id"] = whole(str(settings["anchor_id"]), f"{what} anchor_id")
    return Topic(kind=kind, name=name, **{k: v for k, v in settings.items() if k in allowed})


def field(message, path: str, what: str, type_name: str):
    """The value at a dotted path (a number indexes a list)."""
    value = message
    for part in path.split("."):
        try:
            value = value[int(part)] if part.isdigit() else getattr(value, part)
        except Exception:
            raise BagError(f"{what}: no field '{path}' in {type_name} (at '{part}')") from None
    return value


def number(value, path: str, what: str, type_name: str) -> float:
    if isinstance(value, (list, tuple)):
        raise BagError(f"{what}: field '{path}' of {type_name} is a list of {len(value)} items; give each={path} to "
                       "read one measurement per item")
    try:
        return float(value)
    except (TypeError, ValueError):
        raise BagError(f"{what}: field '{path}' of {type_name} is not a number") from None


def anchor_of_frame(frame_id: str, what: str) -> int:
    found = re.search(r"(\d+)\s*$", frame_id)
    if not found:
        raise BagError(f"{what}: frame_id '{frame_id}' ends in no anchor number; give anchor=PATH or anchor_id=N")
    return whole(found.group(1), what)


def type_name(message) -> str:
    return getattr(message, "_type", type(message).__name__)  # genpy's real ROS name


def stamp(message, recorded, topic: Topic) -> float:
    if topic.time == "bag":
        return recorded.to_sec()
    header = getattr(message, "header", None)
    if header is None:
        raise BagError(f"{topic.what}: {type_name(message)} has no header; add time=bag (when the bag recorded it)")
    return header.stamp.to_sec()


def with_preset(topic: Topic, kind_name: str) -> Topic:
    """The topic's settings over its type's preset (a setting given wins)."""
    preset = (POSE_PRESETS if topic.kind == "pose" else RANGE_PRESETS).get(kind_name, {})
    return replace(topic, **{k: v for k, v in preset.items() if getattr(topic, k) is None})


def pose_rows(topic: Topic, messages) -> Iterator[Tuple]:
    for message, recorded, kind_name in messages:
        if topic.field is None:
            raise BagError(f"{topic.what}: {kind_name} has no preset; give field=PATH (the position)")
        if topic.each and topic.frame is None:
            raise BagError(f"{topic.what}: {kind_name} holds many frames; give frame=NAME (a child_frame_id)")
        t_message = stamp(message, recorded, topic) if not topic.each else None
        items = field(message, topic.each, topic.what, kind_name) if topic.each else [message]
        for item in items:
            if topic.frame is not None and getattr(item, "child_frame_id", None) != topic.frame:
                continue
            t = t_message if t_message is not None else stamp(item, recorded, topic)
            p = field(item, topic.field, topic.what, kind_name)
            xyz = [number(field(p, axis, topic.what, kind_name), f"{topic.field}.{axis}", topic.what, kind_name)
                   for axis in ("x", "y", "z")]
            yield (t, topic.tag, *xyz)


def anchor_id(topic: Topic, message, item, kind_name: str) -> int:
    if topic.anchor_id is not None:
        return topic.anchor_id
    if topic.anchor is not None:
        value = number(field(item, topic.anchor, topic.what, kind_name), topic.anchor, topic.what, kind_name)
        if not value.is_integer():
            raise BagError(f"{topic.what}: anchor id {value!r} (field '{topic.anchor}') is not a whole number; is "
                           "that field the anchor's id?")
        return whole(str(int(value)), topic.what)
    header = getattr(message, "header", None)
    if kind_name == "sensor_msgs/Range" and header is not None:
        return anchor_of_frame(header.frame_id, topic.what)
    raise BagError(f"{topic.what}: {kind_name} names no anchor; give anchor=PATH or anchor_id=N")


def range_rows(topic: Topic, messages) -> Iterator[Tuple]:
    for message, recorded, kind_name in messages:
        if topic.range is None:
            raise BagError(f"{topic.what}: {kind_name} has no preset; give range=PATH and anchor=PATH (or anchor_id=N)")
        t = stamp(message, recorded, topic)
        for item in (field(message, topic.each, topic.what, kind_name) if topic.each else [message]):
            d = number(field(item, topic.range, topic.what, kind_name), topic.range, topic.what, kind_name)
            yield t, topic.tag, anchor_id(topic, message, item, kind_name), d


class Bags:
    """The bags read, each topic from the first bag that holds it."""

    def __init__(self, paths: List[str]):
        import rosbag  # Debian's python3-rosbag

        self.paths, self.bags, self.types = paths, [], []
        for path in paths:
            if not os.path.isfile(path):
                raise BagError(f"{path}: no such bag file")
            try:
                bag = rosbag.Bag(path)
                info = bag.get_type_and_topic_info().topics
            except Exception as error:  # rosbag raises its own ROSBagException and others
                raise BagError(f"{path}: not a readable ROS 1 bag: {first_line(error)}") from None
            self.bags.append(bag)
            self.types.append({name: topic.msg_type for name, topic in info.items()})

    def close(self) -> None:
        for bag in self.bags:
            bag.close()

    def messages(self, topic: Topic) -> Tuple[Topic, Iterator]:
        for path, bag, types in zip(self.paths, self.bags, self.types):
            if topic.name in types:
                kind_name = types[topic.name]
                return with_preset(topic, kind_name), self._read(path, bag, topic, kind_name)
        known = sorted({name for types in self.types for name in types})
        raise BagError(f"{topic.what}: not in the bag{'s' if len(self.paths) > 1 else ''} (topics: "
                       f"{', '.join(known) or 'none'})")

    @staticmethod
    def _read(path, bag, topic: Topic, kind_name: str):
        try:
            for _, message, recorded in bag.read_messages(topics=[topic.name]):
                yield message, recorded, type_name(message) if hasattr(message, "_type") else kind_name
        except BagError:
            raise
        except Exception as error:  # a torn chunk, a bad index, a message that does not decode
            raise BagError(f"{path}: cannot read {topic.name}: {first_line(error)}") from None


def first_line(error: BaseException) -> str:
    text = str(error).strip().splitlines()
    return f"{type(error).__name__}: {text[0] if text else ''}".rstrip(": ")


def collect(bags: Bags, topics: List[Topic], rows) -> List[Tuple]:
    """Every topic's rows, merged in time order (topics in the order given at equal times)."""
    merged = []
    for topic in topics:
        topic, messages = bags.messages(topic)
        merged.extend(rows(topic, messages))
    merged.sort(key=lambda row: row[0])  # stable: equal times keep their topic's order
    return merged


def write(folder: str, name: str, header, rows) -> None:
    with open(os.path.join(folder, name), "w", newline="") as out:
        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(header)
        for row in rows:
            writer.writerow([repr(v) if isinstance(v, float) else v for v in row])
        out.flush()
        os.fsync(out.fileno())


def check_out(out: str, bag_paths: List[str], overwrite: bool, given: str) -> None:
    for path in bag_paths:
        bag = os.path.realpath(path)
        if bag == out or bag.startswith(out + os.sep):
            raise BagError(f"{given}: holds {path}, a bag this reads; choose another output folder")
    if os.path.exists(out) and not os.path.isdir(out):
        raise BagError(f"{given}: exists and is not a folder")
    if os.path.isdir(out) and os.listdir(out) and not overwrite:
        raise BagError(f"{given}: holds earlier files; add --overwrite to replace them")


def convert(args) -> str:
    poses_wanted, ranges_wanted = topics_of(args)
    out = os.path.realpath(args.out)
    check_out(out, args.bag, args.overwrite, args.out)
    bags = Bags(args.bag)
    try:
        poses = collect(bags, poses_wanted, pose_rows)
        ranges = collect(bags, ranges_wanted, range_rows)
    finally:
        bags.close()
    if poses_wanted and not poses:
        raise BagError(f"{', '.join(t.name for t in poses_wanted)}: no poses in the bag: nothing to replay")
    if ranges_wanted and not ranges:
        raise BagError(f"{', '.join(t.name for t in ranges_wanted)}: no ranges in the bag: nothing to replay")
    parent = os.path.dirname(out)
    try:
        os.makedirs(parent, exist_ok=True)
        partial = tempfile.mkdtemp(prefix=f".{os.path.basename(out)}.partial-", dir=parent)
    except OSError as error:
        raise BagError(f"{args.out}: cannot write beside it: {error.strerror}") from None
    try:
        if poses_wanted:
            write(partial, "poses.csv", ["t", "tag_id", "x", "y", "z"], poses)
        if ranges_wanted:
            write(partial, "ranges.csv", ["t", "tag_id", "anchor_id", "range"], ranges)
        if os.path.exists(out):
            shutil.rmtree(out)
        os.rename(partial, out)
    except OSError as error:
        shutil.rmtree(partial, ignore_errors=True)
        raise BagError(f"{args.out}: cannot write: {error.strerror or error}") from None
    except BaseException:
        shutil.rmtree(partial, ignore_errors=True)
        raise
    written = [f"{len(poses)} poses" if poses_wanted else "", f"{len(ranges)} ranges" if ranges_wanted else ""]
    note = "" if poses_wanted else " (no poses: replay with --poses from elsewhere)"
    return f"anchorbench-bag: {', '.join(w for w in written if w)} -> {args.out}{note}"


def topics_of(args) -> Tuple[List[Topic], List[Topic]]:
    """The topics asked for: --pose/--range, with the single-tag flags as their defaults."""
    pose_defaults = {"tag": args.tag_id, "time": args.time, "field": args.position_field}
    range_defaults = {"tag": args.tag_id, "time": args.time, "range": args.range_field, "anchor": args.anchor_field,
                      "each": args.each, "anchor_id": args.anchor_id}
    pose_defaults = {k: v for k, v in pose_defaults.items() if v is not None}
    range_defaults = {k: v for k, v in range_defaults.items() if v is not None}
    poses = [parse_topic("pose", words, pose_defaults) for words in args.pose or []]
    ranges = [parse_topic("range", words, range_defaults) for words in args.range or []]
    if args.pose_topic:
        poses.append(parse_topic("pose", [args.pose_topic], pose_defaults))
    if args.range_topic:
        ranges.append(parse_topic("range", [args.range_topic], range_defaults))
    if not poses and not ranges:
        raise BagError("no topic: give --pose TOPIC and/or --range TOPIC")
    for kind, topics in (("pose", poses), ("range", ranges)):
        names = [t.name for t in topics]
        for name in names:
            if names.count(name) > 1:
                raise BagError(f"--{kind} {name}: given twice; its rows would count twice")
    return poses, ranges


class Parser(argparse.ArgumentParser):
    def error(self, message):  # usage errors as one line, exit 2
        print(f"anchorbench-bag: error: {message} (see anchorbench-bag --help)", file=sys.stderr)
        sys.exit(2)


def parser() -> argparse.ArgumentParser:
    p = Parser(prog="anchorbench-bag", description=__doc__.split("\n\n")[0],
               formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__.split("\n\n", 1)[1])
    p.add_argument("bag", nargs="+", help="ROS 1 bags; each topic is read from the first that holds it")
    p.add_argument("--out", required=True, help="the folder of poses.csv and ranges.csv")
    p.add_argument("--pose", nargs="+", action="append", metavar="TOPIC [KEY=VALUE]",
                   help="a pose topic and its keys (tag, time, field, frame, each); repeatable")
    p.add_argument("--range", nargs="+", action="append", metavar="TOPIC [KEY=VALUE]",
                   help="a range topic and its keys (tag, time, range, anchor, anchor_id, each); repeatable")
    p.add_argument("--pose-topic", help="one pose topic (the single-tag form)")
    p.add_argument("--range-topic", help="one range topic (the single-tag form)")
    p.add_argument("--position-field", help="default field=: the position's path")
    p.add_argument("--range-field", help="default range=: the range's path, m")
    p.add_argument("--anchor-field", help="default anchor=: the anchor id's path")
    p.add_argument("--anchor-id", help="default anchor_id=: one anchor id for every range")
    p.add_argument("--each", help="default each=: a list of measurements in one message")
    p.add_argument("--tag-id", default=None, help="default tag= (0)")
    p.add_argument("--time", choices=["header", "bag"], default=None, help="default time=")
    p.add_argument("--overwrite", action="store_true")
    return p


def main(argv=None) -> int:
    args = parser().parse_args(argv)
    try:
        print(convert(args))
    except BagError as error:
        print(f"anchorbench-bag: error: {error}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("anchorbench-bag: interrupted: nothing written", file=sys.stderr)
        return 130
    return 0


if __name__ == "__main__":
    sys.exit(main())
