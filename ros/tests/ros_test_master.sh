# Sourced by the ROS tests: a scratch folder ($dir), a master on a free loopback port with the
# environment pointing at it, `hall_log SEED DURATION_S MIN_PERIOD_S MAX_PERIOD_S` writing a simulated one-tag hall log
# to $dir/log with $bin, and on exit every process the test started (in $pids) stopped, by id.
dir=$(mktemp -d)  # needs $bin (anchorbench) set by the caller
pids=()
stop() {  # SIGINT is ignored in background jobs: TERM (roslaunch then stops the node it started)
  kill -TERM "$1" 2>/dev/null || true
  wait "$1" 2>/dev/null || true
}
cleanup() {
  for pid in "${pids[@]}"; do stop "$pid"; done
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

# A hall of 10 x 8 x 4 m with 4 anchors, one tag at 20 Hz.
hall_log() {
  cat >"$dir/hall.yaml" <<YAML
seed: $1
scenario:
  environment: hall
  hall: {length_m: 10, width_m: 8, height_m: 4, num_anchors: 4, anchor_height_min_m: 0.5, anchor_height_max_m: 3.5}
  trajectory: {kind: random, height_m: 1.5, vertical_excursion_m: 0.8, hall_duration_s: $2, rate_hz: 20,
               min_period_s: $3, max_period_s: $4}
  ranging: {sigma_range_m: 0.05, outlier_probability: 0.01}
YAML
  "$bin" simulate "$dir/hall.yaml" --out "$dir/log" >/dev/null
}
