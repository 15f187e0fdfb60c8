#!/usr/bin/env bash
# anchorbench_ros fed by `rosbag play` (docs/ros.md): a bag the test writes from a simulated log
# (the tag's body on /tf, one range topic per anchor, and malformed ranges on a topic of all
# anchors), the node started by roslaunch from its package, the bag played at 10x and then, into a
# fresh node, at 1x. Each time the anchors published must equal `anchorbench replay` on the same
# log to print precision, no range may be lost, the malformed ones are counted, and save and reset
# work. A master on a free loopback port; only the processes started here are stopped.
#   ros_bag_play_test.sh PACKAGE_DIR ANCHORBENCH
set -euo pipefail
package=$1 bin=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/ros_test_master.sh"
export ROS_PACKAGE_PATH="$(dirname "$package")${ROS_PACKAGE_PATH:+:$ROS_PACKAGE_PATH}"

# A 30 s hall log, one tag at 20 Hz, its bag, and what replay makes of the bag's data with the
# node's settings.
hall_log 11 30 8 20
cat >"$dir/estimator.yaml" <<'YAML'
estimator: {triggers: [pdop_closest_point], nls: {max_passes: 200}}
YAML
/usr/bin/python3 "$here/ros_bag_write.py" "$dir/log" "$dir/log.bag"
"$bin" replay --poses "$dir/log/poses.csv" --ranges "$dir/log/ranges_f32.csv" --config "$dir/estimator.yaml" \
  --out "$dir/replay" --quiet >/dev/null

cat >"$dir/robot.yaml" <<YAML
config: $dir/estimator.yaml
trigger: pdop_closest_point
save_dir: $dir/saved
tags:
  - id: 0
    pose_type: tf
    body_frame: body0
    offset_m: [0.0, 0.0, 0.1]
    range_topic: /uwb/tag0/all
    range_topics: [{anchor: 0, topic: /uwb/tag0/a0}, {anchor: 1, topic: /uwb/tag0/a1},
                   {anchor: 2, topic: /uwb/tag0/a2}, {anchor: 3, topic: /uwb/tag0/a3}]
YAML

for rate in 10 1; do
  PYTHONUNBUFFERED=1 roslaunch -p "$port" anchorbench_ros anchorbench.launch params:="$dir/robot.yaml" \
    >"$dir/launch_$rate.log" 2>&1 &
  launch=$!
  pids+=($launch)
  /usr/bin/python3 -c 'import rospy; rospy.wait_for_service("/anchorbench/save", timeout=30)' ||
    { echo "FAIL: the node did not come up"; cat "$dir/launch_$rate.log"; exit 1; }
  rosbag play --quiet -d 1 -r "$rate" "$dir/log.bag" >"$dir/play_$rate.log" 2>&1
  /usr/bin/python3 "$here/ros_bag_play_check.py" "$dir/log" "$dir/replay/estimates.csv" "$dir/saved" "$rate" ||
    { echo "--- node log"; cat "$ROS_LOG_DIR"/anchorbench*.log "$dir/launch_$rate.log" 2>/dev/null | tail -40; exit 1; }
  stop "$launch"
done
echo "ros.bag_play: ok"
