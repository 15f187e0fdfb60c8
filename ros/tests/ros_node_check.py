"""Plays a simulated log into anchorbench_ros through a real master and checks what comes out:
each initialized anchor on ~anchor_<id> within D of the log's anchors, a diagnostic per anchor,
~waypoints, and ~save writing anchors.csv. Usage: ros_node_check.py LOG_FOLDER SAVE_DIR"""
import csv
import math
import os
import sys
import time

import rospy
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import PoseArray, PoseStamped, PoseWithCovarianceStamped
from sensor_msgs.msg import Range
from std_srvs.srv import Trigger

LOG, SAVED = sys.argv[1], sys.argv[2]
D = 0.75


def rows(name):
    with open(os.path.join(LOG, name)) as f:
        return list(csv.DictReader(f))


truth = {int(r["anchor_id"]): (float(r["x"]), float(r["y"]), float(r["z"])) for r in rows("anchors.csv")}
rospy.init_node("anchorbench_check", anonymous=True)
poses = rospy.Publisher("/tag0/pose", PoseStamped, queue_size=10000)
ranges = rospy.Publisher("/tag0/ranges", Range, queue_size=10000)
estimates, diagnostics, waypoints = {}, {}, []
for anchor_id in truth:
    rospy.Subscriber(f"/anchorbench/anchor_{anchor_id}", PoseWithCovarianceStamped,
                     lambda m, a=anchor_id: estimates.__setitem__(a, m))
rospy.Subscriber("/diagnostics", DiagnosticArray,
                 lambda m: diagnostics.update({s.name: s for s in m.status if s.name.startswith("anchorbench: anchor")}))
rospy.Subscriber("/anchorbench/waypoints", PoseArray, waypoints.append)
deadline = time.time() + 20
while (poses.get_num_connections() == 0 or ranges.get_num_connections() == 0) and time.time() < deadline:
    time.sleep(0.1)
assert poses.get_num_connections() and ranges.get_num_connections(), "the node never subscribed"

events = [(float(r["t"]), 0, r) for r in rows("poses.csv")] + [(float(r["t"]), 1, r) for r in rows("ranges.csv")]
events.sort(key=lambda e: (e[0], e[1]))
for k, (t, kind, r) in enumerate(events):
    stamp = rospy.Time.from_sec(t)
    if kind == 0:
        m = PoseStamped()
        m.header.stamp, m.header.frame_id = stamp, "world"
        m.pose.position.x, m.pose.position.y, m.pose.position.z = float(r["x"]), float(r["y"]), float(r["z"])
        m.pose.orientation.w = 1.0
        poses.publish(m)
    else:
        m = Range()
        m.header.stamp, m.header.frame_id = stamp, f"anchor_{r['anchor_id']}"
        m.range = float(r["range"])
        ranges.publish(m)
    if k % 200 == 0:
        time.sleep(0.02)  # within the queues' depth

deadline = time.time() + 20
while (not estimates or len(diagnostics) < len(truth)) and time.time() < deadline:
    time.sleep(0.2)
assert estimates, "no anchor was published"
for anchor_id, m in estimates.items():
    p = m.pose.pose.position
    error = math.dist((p.x, p.y, p.z), truth[anchor_id])
    assert error < D, f"anchor {anchor_id} published {error:.2f} m off"
    assert m.pose.covariance[0] > 0 and m.header.frame_id == "world"
assert len(diagnostics) == len(truth), f"diagnostics for {sorted(diagnostics)}"
# ~waypoints, beside ~guidance: a pose per waiting anchor a candidate certifies (none once all are)
assert waypoints and waypoints[-1].header.frame_id == "world", "no ~waypoints"
assert len(waypoints[-1].poses) <= len(truth) - len(estimates)
for status in diagnostics.values():
    keys = {kv.key for kv in status.values}
    assert "trigger" in keys and "samples" in keys, keys

rospy.wait_for_service("/anchorbench/save", timeout=10)
answer = rospy.ServiceProxy("/anchorbench/save", Trigger)()
assert answer.success, answer.message
with open(os.path.join(SAVED, "anchors.csv")) as f:
    saved = list(csv.DictReader(f))
assert {int(r["anchor_id"]) for r in saved} == set(estimates), (saved, sorted(estimates))
assert os.path.exists(os.path.join(SAVED, "anchors.yaml"))
print(f"ros node: {len(estimates)} of {len(truth)} anchors published within {D} m; diagnostics for all; saved")
