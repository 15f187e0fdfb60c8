#!/usr/bin/env bash
# anchorbench_ros against a real ROS master (docs/ros.md): a master on a free loopback port, the
# node with one tag, a simulated log played through rospy, then the anchors topic, the diagnostics
# and the save service checked against the log's anchors; and a bad parameter refused in one line.
#   ros_node_test.sh NODE ANCHORBENCH
set -euo pipefail
node=$1 bin=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/ros_test_master.sh"

# A bad parameter: one line, exit 2, before anything is subscribed.
set +e
rosparam set /bad/tags "[{id: 0, pose_topic: p, pose_type: Pose, range_topic: r}]"
"$node" __name:=bad >"$dir/bad.log" 2>&1
code=$?
set -e
[ $code -eq 2 ] || { echo "FAIL: bad pose_type exited $code"; cat "$dir/bad.log"; exit 1; }
grep -q "tags\[0\].pose_type" "$dir/bad.log" || { echo "FAIL: the refusal does not name the parameter"; cat "$dir/bad.log"; exit 1; }
rosparam set /bad/tags "[{id: 0, pose_type: tf, range_topics: [{anchor: 1, topic: r}]}]"
set +e
"$node" __name:=bad >"$dir/bad.log" 2>&1
code=$?
set -e
[ $code -eq 2 ] && grep -q "tags\[0\].body_frame" "$dir/bad.log" ||
  { echo "FAIL: tf without body_frame: exit $code"; cat "$dir/bad.log"; exit 1; }

# A small hall, 60 s, one tag: the log the node is fed.
hall_log 4 60 10 30

# The node's parameters as a robot's file gives them (docs/ros.md, ros/config/robot.yaml).
cat >"$dir/robot.yaml" <<YAML
trigger: pdop_closest_point
save_dir: $dir/saved
tags:
  - {id: 0, pose_topic: /tag0/pose, pose_type: PoseStamped, offset_m: [0, 0, 0], range_topic: /tag0/ranges}
YAML
rosparam load "$dir/robot.yaml" /anchorbench
"$node" __name:=anchorbench >"$dir/node.log" 2>&1 &
pids+=($!)
/usr/bin/python3 "$here/ros_node_check.py" "$dir/log" "$dir/saved" || { echo "--- node log"; cat "$dir/node.log"; exit 1; }
echo "ros.node: ok"
