#pragma once
// What the ROS node knows of every anchor, without ROS: the live front end with the config's
// chains, the one trigger whose initializations the robot uses, each anchor's estimate or what it
// waits for, and the anchors as files (docs/ros.md). Any thread may call it.
//
// This header is C++17 with std and Eigen only: ROS 1's message headers do not compile as C++20
// (std::allocator<void>::rebind), so the node's ROS side sees the core through it alone.

#include <chrono>
#include <cstddef>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace anchorbench::ros_node {

// A setting the node cannot run with: one line naming it (the config's file and key, or the
// parameter).
class BadSetting : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct AnchorState {
  int anchor_id = 0;
  bool initialized = false;
  // Initialized: the estimate, its position covariance, when and on how many samples.
  Eigen::Vector3d p_world_anchor = Eigen::Vector3d::Zero();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  double bias_m = 0.0;
  double t_init_s = 0.0;
  int n_used = 0;
  std::string status;
  std::string waiting_for;  // not initialized: the test that holds it back, with its numbers
  long samples = 0;         // buffered by the published trigger's chain
};

// Where to range from next for an anchor the published trigger still waits for (docs/guidance.md).
struct AnchorGuide {
  int anchor_id = 0;
  std::string blocked_by;   // the test that holds it now (the forecast is the region's)
  double region_m = 0.0;    // the region's radius now, and D
  double accuracy_m = 0.0;
  std::vector<Eigen::Vector3d> p_world_candidate;  // the best first
  std::vector<double> samples_to_certify;          // each one's (+inf: never from there alone)
  double seconds_to_certify = 0.0;                 // the fewest of them at the link's rate
};

// Where to go next, for a planner (the node's ~waypoints): each waiting anchor's best candidate,
// where ranging there brings its region within D, the soonest first (ties: the lower anchor id).
// As the closed-loop study flies them (docs/guidance.md): an anchor no candidate closes has none.
std::vector<Eigen::Vector3d> WaypointsOf(const std::vector<AnchorGuide>& guides);

// What came in and what the front end did not use, for the node's diagnostics.
struct InputCounts {
  long poses = 0, ranges = 0;        // handed to the front end
  long malformed_ranges = 0;         // refused by the node (no anchor id, not a positive finite range)
  long samples = 0;                  // ranges placed on a pose and given to the anchors' chains
  long ranges_outside_poses = 0, ranges_without_pose = 0, poses_ignored = 0, ranges_beyond_max_anchors = 0;
};

class AnchorMap {
 public:
  using Clock = std::chrono::steady_clock;
  // The CLI's config (a YAML path, empty: the defaults) with KEY=VALUE overrides, and the trigger
  // whose initializations are published (empty: certified where the config lists it, else the
  // first online one). Throws BadSetting.
  AnchorMap(const std::string& config_path, const std::vector<std::string>& overrides, const std::string& trigger);
  ~AnchorMap();

  void AddPose(double t_s, int tag_id, const Eigen::Vector3d& p_world_tag);
  void AddRange(double t_s, int tag_id, int anchor_id, double range_m);
  void CountMalformedRange();
  InputCounts Counts() const;
  // Runs due solves (at most max_count, none after deadline) and returns the anchors the published
  // trigger initialized since the last call.
  std::vector<AnchorState> Step(std::size_t max_count, Clock::time_point deadline);
  // Every anchor seen, ascending: initialized or what it waits for.
  std::vector<AnchorState> States() const;
  // Guidance for every waiting anchor whose trigger judges a region (certified): the `best`
  // candidates on a grid reach_m around its last tag position (`steps` a side), by the region after
  // 50 more ranges there, at range_rate_hz.
  std::vector<AnchorGuide> Guide(double reach_m, int steps, std::size_t best, double range_rate_hz) const;
  void Reset();
  bool Reset(int anchor_id);  // false: no such anchor
  const std::string& trigger() const;
  std::size_t pending_solves() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// anchors.csv (anchor_id,x,y,z,bias, as replay --anchors reads it, plus t_init,n_used and the
// position covariance's diagonal) and the same as YAML, of the initialized anchors.
std::string AnchorsCsv(const std::vector<AnchorState>& anchors);
std::string AnchorsYaml(const std::vector<AnchorState>& anchors, const std::string& frame_id);
// Both into `folder` (made if missing), each file whole or not at all (io::AtomicFile, replacing an
// earlier save); throws std::runtime_error naming the file.
void SaveAnchors(const std::string& folder, const std::vector<AnchorState>& anchors, const std::string& frame_id);

// The 99% ellipsoid of a 3x3 covariance: its axes' full lengths (m) and orientation.
struct Ellipsoid {
  Eigen::Vector3d diameters_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};
Ellipsoid EllipsoidOf(const Eigen::Matrix3d& covariance, double confidence = 0.99);

// The anchor id a range message names in its frame_id: the trailing digits ("anchor_12", "12").
std::optional<int> AnchorIdFromFrame(const std::string& frame_id);

}  // namespace anchorbench::ros_node
