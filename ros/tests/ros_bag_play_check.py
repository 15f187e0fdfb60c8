"""Checks the node after a bag was played into it: every range counted (none lost, the two
malformed ones reported), each anchor that replay initialized published with replay's numbers to
print precision (1e-6 m; the stamps are whole nanoseconds) and no other, drawn as markers, the save service, and the
reset service (every anchor waiting, the markers cleared). Usage:
ros_bag_play_check.py LOG_FOLDER REPLAY_ESTIMATES SAVE_DIR RATE"""
import csv
import os
import sys
import time

import rospy
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import PoseWithCovarianceStamped
from std_srvs.srv import Empty, Trigger
from visualization_msgs.msg import Marker, MarkerArray

LOG, EXPECTED, SAVED, RATE = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
T0_S = 1000.0  # ros_bag_write.py's clock


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


expected = {int(r["anchor_id"]): r for r in rows(EXPECTED) if r["initialized"] == "1"}
n_ranges = len(rows(os.path.join(LOG, "ranges.csv")))
n_poses = len(rows(os.path.join(LOG, "poses.csv")))
anchor_ids = sorted({int(r["anchor_id"]) for r in rows(os.path.join(LOG, "anchors.csv"))})
assert expected, "replay initialized no anchor: the log does not test the node"

rospy.init_node("anchorbench_bag_check", anonymous=True)
published, status = {}, {}
for anchor_id in anchor_ids:
    rospy.Subscriber(f"/anchorbench/anchor_{anchor_id}", PoseWithCovarianceStamped,
                     lambda m, a=anchor_id: published.__setitem__(a, m))
markers = []
rospy.Subscriber("/anchorbench/markers", MarkerArray, lambda m: markers.append(m))
rospy.Subscriber("/diagnostics", DiagnosticArray,
                 lambda m: status.update({s.name: {kv.key: kv.value for kv in s.values} for s in m.status}))


def wait_for(what, done, seconds=20):
    deadline = time.time() + seconds
    while not done() and time.time() < deadline:
        time.sleep(0.1)
    assert done(), f"at {RATE}x: {what} (diagnostics: {status.get('anchorbench: input')})"


def counted(key):
    return int(status.get("anchorbench: input", {}).get(key, -1))


wait_for(f"{n_ranges} ranges and 2 malformed ones counted",
         lambda: counted("ranges") == n_ranges and counted("malformed_ranges") == 2)
assert counted("poses") == n_poses, (counted("poses"), n_poses)
wait_for("replay's anchors published", lambda: set(published) >= set(expected))
time.sleep(0.5)
assert set(published) == set(expected), f"published {sorted(published)}, replay initialized {sorted(expected)}"
for anchor_id, row in expected.items():
    p = published[anchor_id].pose.pose.position
    for axis, value in zip("xyz", (p.x, p.y, p.z)):
        assert abs(value - float(row[axis])) <= 1e-6, f"at {RATE}x: anchor {anchor_id} {axis} {value} != {row[axis]}"
    assert abs(published[anchor_id].header.stamp.to_sec() - (T0_S + float(row["t_init"]))) < 1e-6

drawn = [m for m in markers[-1].markers if m.action == Marker.ADD]
assert sorted(m.id for m in drawn if m.type == Marker.SPHERE) == [2 * a for a in sorted(expected)], drawn
assert all(m.scale.x > 0 and m.color.a > 0 for m in drawn if m.type == Marker.SPHERE)
assert sorted(m.text for m in drawn if m.type == Marker.TEXT_VIEW_FACING) == \
    sorted(f"anchor {a} ({expected[a]['status']})" for a in expected)

save = rospy.ServiceProxy("/anchorbench/save", Trigger)()
assert save.success, save.message
assert {int(r["anchor_id"]) for r in rows(os.path.join(SAVED, "anchors.csv"))} == set(expected)

rospy.ServiceProxy("/anchorbench/reset", Empty)()
status.clear()
wait_for("every anchor waiting after reset",
         lambda: all(f"anchorbench: anchor {a}" in status for a in anchor_ids) and
         all("waiting_for" in status[f"anchorbench: anchor {a}"] for a in anchor_ids))
wait_for("the markers cleared after reset",
         lambda: markers and not [m for m in markers[-1].markers if m.action == Marker.ADD])
print(f"at {RATE}x: {n_ranges} ranges counted, 2 malformed; {len(expected)} anchors as replay's; saved; reset")
