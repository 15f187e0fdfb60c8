"""anchorbench-bag on small bags written here with python3-rosbag: presets, field paths, refusals."""

import numpy as np
import pytest

rosbag = pytest.importorskip("rosbag")
import rospy  # noqa: E402
from geometry_msgs.msg import PoseStamped, TransformStamped  # noqa: E402
from nav_msgs.msg import Odometry  # noqa: E402
from sensor_msgs.msg import Range  # noqa: E402
from std_msgs.msg import Float64MultiArray  # noqa: E402

import anchorbench as ab  # noqa: E402
from anchorbench import bag as converter  # noqa: E402

ANCHORS = {3: np.array([2.0, -1.0, 4.0]), 5: np.array([-3.0, 2.0, 1.0])}


def positions(n=200):
    t = np.arange(n) * 0.1
    p = np.column_stack([4 * np.cos(t / 3), 4 * np.sin(t / 2), 1.5 + np.sin(t)])
    return t, p


def write_bag(path, pose_kind="pose", range_kind="range"):
    t, p = positions()
    with rosbag.Bag(str(path), "w") as bag:
        for ti, pi in zip(t, p):
            stamp = rospy.Time.from_sec(100.0 + ti)
            if pose_kind == "pose":
                m = PoseStamped()
                m.header.stamp = stamp
                m.pose.position.x, m.pose.position.y, m.pose.position.z = pi
            elif pose_kind == "odometry":
                m = Odometry()
                m.header.stamp = stamp
                m.pose.pose.position.x, m.pose.pose.position.y, m.pose.pose.position.z = pi
            else:
                m = TransformStamped()
                m.header.stamp = stamp
                m.transform.translation.x, m.transform.translation.y, m.transform.translation.z = pi
            bag.write("/tag/pose", m, stamp)
            for anchor, p_anchor in ANCHORS.items():
                d = float(np.linalg.norm(pi - p_anchor))
                if range_kind == "range":
                    r = Range()
                    r.header.stamp = stamp
                    r.header.frame_id = f"anchor_{anchor}"
                    r.range = d
                else:
                    r = Float64MultiArray(data=[float(anchor), d])
                bag.write("/uwb", r, stamp)
    return t, p


@pytest.mark.parametrize("pose_kind", ["pose", "odometry", "transform"])
def test_presets_give_the_replay_csvs(tmp_path, pose_kind):
    t, p = write_bag(tmp_path / "run.bag", pose_kind)
    status = converter.main([str(tmp_path / "run.bag"), "--out", str(tmp_path / "log"), "--pose-topic", "/tag/pose",
                             "--range-topic", "/uwb"])
    assert status == 0
    poses = np.genfromtxt(tmp_path / "log" / "poses.csv", delimiter=",", names=True)
    ranges = np.genfromtxt(tmp_path / "log" / "ranges.csv", delimiter=",", names=True)
    assert len(poses) == len(t) and len(ranges) == 2 * len(t)
    assert np.allclose(poses["t"], 100.0 + t) and np.allclose(poses["x"], p[:, 0])
    assert set(ranges["anchor_id"].astype(int)) == {3, 5}
    replayed = ab.replay(tmp_path / "log" / "poses.csv", tmp_path / "log" / "ranges.csv")
    assert set(replayed.estimates["anchor_id"]) == {3, 5}


def test_field_paths_read_a_message_without_a_preset(tmp_path):
    write_bag(tmp_path / "run.bag", range_kind="array")
    args = [str(tmp_path / "run.bag"), "--out", str(tmp_path / "log"), "--pose-topic", "/tag/pose", "--range-topic",
            "/uwb", "--time", "bag"]
    assert converter.main(args) == 2  # no preset and no field paths: refused
    assert not (tmp_path / "log").exists()
    assert converter.main(args + ["--range-field", "data.1", "--anchor-field", "data.0"]) == 0
    ranges = np.genfromtxt(tmp_path / "log" / "ranges.csv", delimiter=",", names=True)
    assert set(ranges["anchor_id"].astype(int)) == {3, 5}


def test_refusals_are_one_line_and_leave_nothing(tmp_path, capsys):
    write_bag(tmp_path / "run.bag")
    base = [str(tmp_path / "run.bag"), "--out", str(tmp_path / "log"), "--range-topic", "/uwb"]
    assert converter.main(base + ["--pose-topic", "/missing"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--pose-topic /missing: not in the bag (its topics: /tag/pose, /uwb)" in err
    assert not (tmp_path / "log").exists()
    assert converter.main(base + ["--pose-topic", "/tag/pose"]) == 0
    assert converter.main(base + ["--pose-topic", "/tag/pose"]) == 2
    assert "exists; add --overwrite" in capsys.readouterr().err
    (tmp_path / "not.bag").write_text("no bag")
    assert converter.main([str(tmp_path / "not.bag"), "--out", str(tmp_path / "x"), "--pose-topic", "/a",
                           "--range-topic", "/b"]) == 2
    assert "not a readable ROS 1 bag" in capsys.readouterr().err
