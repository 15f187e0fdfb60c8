#!/usr/bin/env bash
# anchorbench_ros against a real ROS master (docs/ros.md): a master on a free loopback port, the
# node with one tag, a simulated log played through rospy, then the anchors topic, the diagnostics
# and the save service checked against the log's anchors; and a bad parameter refused in one line.
#   ros_node_test.sh NODE ANCHORBENCH
set -euo pipefail
node=$1 bin=$2
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  rm -rf "$dir"
}
trap cleanup EXIT

port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
export ROS_MASTER_URI="http://127.0.0.1:$port" ROS_HOSTNAME=127.0.0.1 ROS_HOME="$dir/ros_home" ROS_LOG_DIR="$dir/ros_log"
rosmaster --core -p "$port" >"$dir/master.log" 2>&1 &
pids+=($!)
for _ in $(seq 50); do
  /usr/bin/python3 -c 'import rosgraph, sys; sys.exit(0 if rosgraph.is_master_online() else 1)' 2>/dev/null && break
  sleep 0.2
done

# A bad parameter: one line, exit 2, before anything is subscribed.
set +e
rosparam set /bad/tags "[{id: 0, pose_topic: p, pose_type: Pose, range_topic: r}]"
"$node" __name:=bad >"$dir/bad.log" 2>&1
code=$?
set -e
[ $code -eq 2 ] || { echo "FAIL: bad pose_type exited $code"; cat "$dir/bad.log"; exit 1; }
grep -q "tags\[0\].pose_type" "$dir/bad.log" || { echo "FAIL: the refusal does not name the parameter"; cat "$dir/bad.log"; exit 1; }

# A small hall, 60 s, one tag: the log the node is fed.
cat >"$dir/hall.yaml" <<'YAML'
seed: 4
scenario:
  environment: hall
  hall: {length_m: 10, width_m: 8, height_m: 4, num_anchors: 4, anchor_height_min_m: 0.5, anchor_height_max_m: 3.5}
  trajectory: {kind: random, height_m: 1.5, vertical_excursion_m: 0.8, hall_duration_s: 60, rate_hz: 20,
               min_period_s: 10, max_period_s: 30}
  ranging: {sigma_range_m: 0.05, outlier_probability: 0.01}
YAML
"$bin" simulate "$dir/hall.yaml" --out "$dir/log" >/dev/null

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
