#!/usr/bin/env bash
# Installs the Debian 12 packages anchorbench needs. As root it runs apt-get; otherwise it prints
# the exact command to run and fails. Does nothing when everything is already installed.
set -euo pipefail

packages=(
  cmake g++ make                 # toolchain
  libeigen3-dev                  # linear algebra
  libnlopt-cxx-dev               # NLopt, C++ API (alpha search of the adaptive kernel)
  libyaml-cpp-dev libcli11-dev   # configs, command line
  nlohmann-json3-dev             # manifests and summaries (JSON)
  libgtest-dev libgmock-dev      # tests
  libbenchmark-dev               # benchmarks
  python3-matplotlib python3-numpy  # plot_scripts/ (run with /usr/bin/python3)
  clang libclang-rt-14-dev libomp-14-dev  # scripts/sanitize.sh: ASan, UBSan, libFuzzer
  openmpi-bin libopenmpi-dev     # anchorbench-mpi (docs/cluster.md)
  slurm-wlm munge                # scripts/slurm/, tested against a single-node Slurm
  pybind11-dev python3-dev python3-pandas python3-yaml python3-pytest  # the Python module (docs/python.md)
  python3-tqdm python3-hypothesis  # progress bars; property tests of the module and the bag tool
  python3-rosbag python3-genpy python3-geometry-msgs python3-sensor-msgs python3-nav-msgs python3-std-msgs python3-tf2-msgs  # anchorbench-bag
  libroscpp-dev libgeometry-msgs-dev libsensor-msgs-dev libnav-msgs-dev libvisualization-msgs-dev  # anchorbench_ros
  libdiagnostic-msgs-dev libstd-srvs-dev libstd-msgs-dev libtf2-ros-dev  # (docs/ros.md), and its tests against a real master:
  ros-core python3-rosmaster python3-rosparam python3-rospy python3-rosgraph python3-roslaunch
  python3-diagnostic-msgs python3-std-srvs python3-visualization-msgs
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -eq 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "setup: missing Debian packages; run:" >&2
  echo "  sudo apt-get install -y ${missing[*]}" >&2
  exit 1
fi
