"""A ROS 1 bag from a simulated log (poses.csv, ranges.csv of tag 0), as a robot records it: the
body's pose on /tf (world -> body0, the antenna 0.1 m above the body's origin; stamps 1000 s on), each anchor's
ranges on a topic of its own, and on a topic of all anchors two malformed ranges (no anchor id in
frame_id; a NaN). sensor_msgs/Range holds a float32: the ranges as the bag has them go to
LOG_FOLDER/ranges_f32.csv, for replay to see the same data. Usage: ros_bag_write.py LOG_FOLDER BAG"""
import csv
import math
import os
import struct
import sys

import rosbag
import rospy
from geometry_msgs.msg import TransformStamped
from sensor_msgs.msg import Range
from tf2_msgs.msg import TFMessage

LOG, BAG = sys.argv[1], sys.argv[2]
OFFSET_Z_M = 0.1
T0_S = 1000.0  # stamps as a robot's clock gives them, not at zero (ros::Time(0) means "no time")


def rows(name):
    with open(os.path.join(LOG, name)) as f:
        return list(csv.DictReader(f))


def float32(x):
    return struct.unpack("f", struct.pack("f", float(x)))[0]


def stamp_of(t):
    return rospy.Time.from_sec(T0_S + float(t))


with rosbag.Bag(BAG, "w") as bag:
    for r in rows("poses.csv"):
        t = TransformStamped()
        t.header.stamp, t.header.frame_id, t.child_frame_id = stamp_of(r["t"]), "world", "body0"
        t.transform.translation.x, t.transform.translation.y = float(r["x"]), float(r["y"])
        t.transform.translation.z = float(r["z"]) - OFFSET_Z_M
        t.transform.rotation.w = 1.0
        bag.write("/tf", TFMessage(transforms=[t]), t.header.stamp)
    ranges = rows("ranges.csv")
    for r in ranges:
        r["range"] = repr(float32(r["range"]))
        m = Range()
        m.header.stamp, m.header.frame_id = stamp_of(r["t"]), "uwb"  # the topic names the anchor
        m.range, m.max_range = float(r["range"]), 0.0
        bag.write(f"/uwb/tag0/a{r['anchor_id']}", m, m.header.stamp)
    for k, (frame, value) in enumerate((("bogus", 3.0), ("anchor_1", math.nan))):
        m = Range()
        m.header.stamp, m.header.frame_id = stamp_of(float(ranges[100 * (k + 1)]["t"])), frame
        m.range = value
        bag.write("/uwb/tag0/all", m, m.header.stamp)

with open(os.path.join(LOG, "ranges_f32.csv"), "w", newline="") as f:
    out = csv.DictWriter(f, fieldnames=list(ranges[0]))
    out.writeheader()
    out.writerows(ranges)
