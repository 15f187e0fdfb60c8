"""anchorbench-bag on small bags written here with python3-rosbag: presets, field paths, refusals."""

import os

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
    assert err.count("\n") == 1 and "--pose /missing: not in the bag (topics: /tag/pose, /uwb)" in err
    assert not (tmp_path / "log").exists()
    assert converter.main(base + ["--pose-topic", "/tag/pose"]) == 0
    assert converter.main(base + ["--pose-topic", "/tag/pose"]) == 2
    assert "holds earlier files; add --overwrite" in capsys.readouterr().err
    (tmp_path / "not.bag").write_text("no bag")
    assert converter.main([str(tmp_path / "not.bag"), "--out", str(tmp_path / "x"), "--pose-topic", "/a",
                           "--range-topic", "/b"]) == 2
    assert "not a readable ROS 1 bag" in capsys.readouterr().err


# --- Real multi-tag bags (issue 36) and every refusal one line (issue 33) ----------------------------

LINKTRACK = """uint8 role
uint8 id
uint32 local_time
uint32 system_time
float32 voltage
float32[3] pos_3d
float32[3] eop_3d
float32[3] vel_3d
float32[3] angle_3d
float32[4] quaternion
float32[3] imu_gyro_3d
float32[3] imu_acc_3d
LinktrackNode2[] nodes
================================================================================
MSG: nlink_parser/LinktrackNode2
uint8 role
uint8 id
float32 dis
float32 fp_rssi
float32 rx_rssi
"""
UWB_TYPE = "float32 angle\nfloat32 distance\n"  # a range without an anchor id, and without a header


def message_classes():
    import genpy.dynamic

    classes = genpy.dynamic.generate_dynamic("nlink_parser/LinktrackNodeframe2", LINKTRACK)
    uwb = genpy.dynamic.generate_dynamic("my_msgs/uwb_type", UWB_TYPE)
    return classes["nlink_parser/LinktrackNodeframe2"], classes["nlink_parser/LinktrackNode2"], uwb["my_msgs/uwb_type"]


def write_linktrack_bag(path, tags=(1, 2, 3)):
    """Mocap PoseStamped per tag at 20 Hz with its own stamps, LinkTrack frames per tag at 10 Hz
    (recorded 5 ms after the pose), and one anchor's ranges in my_msgs/uwb_type on another topic."""
    Frame, Node, Uwb = message_classes()
    t, p = positions(300)
    offsets = {tag: np.array([0.3 * tag, 0.0, 0.0]) for tag in tags}
    with rosbag.Bag(str(path), "w") as bag:
        for k, (ti, pi) in enumerate(zip(t, p)):
            for tag in tags:
                m = PoseStamped()
                m.header.stamp = rospy.Time.from_sec(50.0 + ti)
                m.pose.position.x, m.pose.position.y, m.pose.position.z = pi + offsets[tag]
                bag.write(f"/mocap/tag{tag}", m, rospy.Time.from_sec(50.0 + ti))
                if k % 2 == 0:
                    frame = Frame(id=tag, nodes=[Node(id=a, dis=float(np.linalg.norm(pi + offsets[tag] - pa)))
                                                 for a, pa in ANCHORS.items()])
                    bag.write(f"/nlink/tag{tag}", frame, rospy.Time.from_sec(50.005 + ti))
            if k % 2 == 0:
                uwb = Uwb(angle=0.0, distance=float(np.linalg.norm(pi + offsets[tags[0]] - ANCHORS[5])))
                bag.write("/uwb_plain", uwb, rospy.Time.from_sec(50.005 + ti))
    return t


def convert(tmp_path, *args):
    return converter.main([str(a) for a in args])


def test_a_linktrack_bag_with_three_tags_converts_in_one_run(tmp_path):
    t = write_linktrack_bag(tmp_path / "lt.bag")
    args = [tmp_path / "lt.bag", "--out", tmp_path / "log"]
    for tag in (1, 2, 3):
        args += ["--pose", f"/mocap/tag{tag}", f"tag={tag}", "--range", f"/nlink/tag{tag}", f"tag={tag}"]
    assert convert(tmp_path, *args) == 0
    poses = np.genfromtxt(tmp_path / "log" / "poses.csv", delimiter=",", names=True)
    ranges = np.genfromtxt(tmp_path / "log" / "ranges.csv", delimiter=",", names=True)
    assert len(poses) == 3 * len(t) and len(ranges) == 3 * 2 * len(t[::2])
    assert np.all(np.diff(poses["t"]) >= 0) and np.all(np.diff(ranges["t"]) >= 0)  # merged in time order
    assert set(poses["tag_id"].astype(int)) == {1, 2, 3} and set(ranges["anchor_id"].astype(int)) == {3, 5}
    # Each tag's ranges at its own offset: replayed, every anchor lands where it is.
    replayed = ab.replay(tmp_path / "log" / "poses.csv", tmp_path / "log" / "ranges.csv",
                         config={"estimator": {"triggers": ["fixed_window"]}})
    estimates = replayed.estimates.set_index("anchor_id")
    for anchor, p_anchor in ANCHORS.items():
        assert np.linalg.norm(estimates.loc[anchor, ["x", "y", "z"]].to_numpy(float) - p_anchor) < 0.05


def test_ranges_only_with_a_constant_anchor_and_poses_from_another_bag(tmp_path):
    write_linktrack_bag(tmp_path / "lt.bag")
    write_bag(tmp_path / "other.bag")
    assert convert(tmp_path, tmp_path / "lt.bag", "--out", tmp_path / "ranges_only",
                   "--range", "/uwb_plain", "tag=1", "range=distance", "anchor_id=5", "time=bag") == 0
    assert sorted(os.listdir(tmp_path / "ranges_only")) == ["ranges.csv"]
    ranges = np.genfromtxt(tmp_path / "ranges_only" / "ranges.csv", delimiter=",", names=True)
    assert set(ranges["anchor_id"].astype(int)) == {5} and set(ranges["tag_id"].astype(int)) == {1}
    # Poses of one bag, ranges of another, in one run.
    assert convert(tmp_path, tmp_path / "other.bag", tmp_path / "lt.bag", "--out", tmp_path / "both",
                   "--pose", "/tag/pose", "--range", "/nlink/tag1") == 0


def test_a_list_field_hints_at_each_and_the_real_type_name_is_said(tmp_path, capsys):
    write_linktrack_bag(tmp_path / "lt.bag")
    write_bag(tmp_path / "array.bag", range_kind="array")
    assert convert(tmp_path, tmp_path / "array.bag", "--out", tmp_path / "x", "--range", "/uwb", "range=data",
                   "anchor_id=1", "time=bag") == 2
    assert ("field 'data' of std_msgs/Float64MultiArray is a list of 2 items; give each=data"
            in capsys.readouterr().err)
    assert convert(tmp_path, tmp_path / "lt.bag", "--out", tmp_path / "x", "--range", "/uwb_plain",
                   "range=distance", "anchor_id=5") == 2
    assert "my_msgs/uwb_type has no header; add time=bag" in capsys.readouterr().err
    assert convert(tmp_path, tmp_path / "lt.bag", "--out", tmp_path / "x", "--range", "/uwb_plain",
                   "time=bag", "anchor_id=5") == 2
    assert "my_msgs/uwb_type has no preset" in capsys.readouterr().err
    assert not (tmp_path / "x").exists()


def refusal(capsys, status, expected):
    err = capsys.readouterr().err
    assert status == 2 and expected in err, err
    assert err.count("\n") == 1, err


def test_every_refusal_is_one_line_and_loses_nothing(tmp_path, capsys):
    write_bag(tmp_path / "run.bag", range_kind="array")
    bag, out = tmp_path / "run.bag", tmp_path / "log"
    common = ["--pose", "/tag/pose", "--out"]
    # The bag's own folder as --out, even with --overwrite: the bag is never deleted.
    refusal(capsys, convert(tmp_path, bag, *common, tmp_path, "--overwrite", "--range", "/uwb", "time=bag",
                            "range=data.1", "anchor=data.0"), "a bag this reads")
    assert bag.exists()
    (tmp_path / "afile").write_text("x")
    refusal(capsys, convert(tmp_path, bag, *common, tmp_path / "afile", "--range", "/uwb", "time=bag",
                            "range=data.1", "anchor=data.0"), "exists and is not a folder")
    refusal(capsys, convert(tmp_path, bag, "--pose", "/tag/pose", "field=pose.nowhere", "--out", out),
            "no field 'pose.nowhere' in geometry_msgs/PoseStamped")
    refusal(capsys, convert(tmp_path, bag, "--out", out, "--range", "/uwb", "time=bag", "range=data.9",
                            "anchor=data.0"), "no field 'data.9'")
    # A range read as the anchor id: 3.45 is no id, never cut to 3.
    refusal(capsys, convert(tmp_path, bag, "--out", out, "--range", "/uwb", "time=bag", "range=data.1",
                            "anchor=data.1"), "is not a whole number; is that field the anchor's id?")
    refusal(capsys, convert(tmp_path, bag, "--out", out, "--range", "/uwb", "time=bag", "range=data.1",
                            "each=data"), "no field")
    refusal(capsys, convert(tmp_path, bag, "--out", out, "--range", "/uwb", "colour=red"), "'colour=red' is not one of")
    refusal(capsys, convert(tmp_path, bag, "--out", out, "--pose", "/tag/pose", "--pose", "/tag/pose"), "given twice")
    refusal(capsys, convert(tmp_path, bag, "--out", out), "no topic")
    assert not out.exists()


def test_a_corrupt_bag_is_one_line(tmp_path, capsys):
    write_bag(tmp_path / "run.bag")
    data = bytearray((tmp_path / "run.bag").read_bytes())
    cases = {"torn": data[: len(data) // 2], "zeroed": data[:4096] + bytes(len(data) - 8192) + data[-4096:],
             "flipped": bytes(b ^ 0x5A if 6000 < i < 9000 else b for i, b in enumerate(data)),
             "header_only": data[:13], "empty": b""}
    for name, content in cases.items():
        path = tmp_path / f"{name}.bag"
        path.write_bytes(bytes(content))
        status = convert(tmp_path, path, "--out", tmp_path / name, "--pose", "/tag/pose", "--range", "/uwb")
        err = capsys.readouterr().err
        assert status in (0, 2), (name, err)
        if status == 2:
            assert err.count("\n") == 1 and err.startswith("anchorbench-bag: error: "), (name, err)
        else:
            assert (tmp_path / name / "poses.csv").exists()


def test_the_script_runs_from_the_source_tree(tmp_path):
    import subprocess
    import sys

    write_bag(tmp_path / "run.bag")
    script = os.path.join(os.environ.get("ANCHORBENCH_SOURCE_DIR", "."), "python", "anchorbench-bag")
    if not os.path.exists(script):
        pytest.skip("ANCHORBENCH_SOURCE_DIR does not name the source tree")
    done = subprocess.run([sys.executable, script, str(tmp_path / "run.bag"), "--out", str(tmp_path / "log"),
                           "--pose-topic", "/tag/pose", "--range-topic", "/uwb"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
