#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/estimator/enum_names.hpp"
#include "anchorbench/sim/environment.hpp"
#include "anchorbench/sim/environment_model.hpp"
#include "anchorbench/sim/range_model.hpp"
#include "anchorbench/sim/trajectory.hpp"

namespace anchorbench::sim {

enum class EnvironmentKind { kTunnel, kHall };
inline constexpr estimator::EnumNames<EnvironmentKind, 2> kEnvironmentKindNames({
    {EnvironmentKind::kTunnel, "tunnel"}, {EnvironmentKind::kHall, "hall"}});
inline std::string_view ToString(EnvironmentKind value) { return kEnvironmentKindNames.Name(value); }
inline bool ParseEnvironmentKind(std::string_view name, EnvironmentKind* value) { return kEnvironmentKindNames.Parse(name, value); }

struct ScenarioOptions {
  // Random sub-streams are keyed (tag << 16 | anchor id) in 24 bits (RandomStream): with at most
  // kMaxTags tags and kMaxAnchors anchors (environment.hpp) the keys stay distinct.
  static constexpr int kMaxTags = 16;
  // The work one realization may imply, checked before any is done: tag positions (epochs x
  // tags, ~100 bytes each) and range slots (epochs x tags x anchors: every range the run could
  // produce, ~100 bytes each in the scenario and the runner's samples). 1e7 and 2e7 keep one
  // realization within ~1 and ~2 GB; Table I uses 2e3 epochs and 6e4 slots.
  static constexpr double kMaxTagEpochs = 1e7;
  static constexpr double kMaxRangeSlots = 2e7;

  EnvironmentKind environment = EnvironmentKind::kTunnel;
  // An environment of the caller's registry (registry::Components::environments) in place of the
  // tunnel or the hall: its name, its options as the config set them (by environment name), and
  // the environment the registry built from them when the config was read.
  std::string custom_environment;
  std::map<std::string, std::map<std::string, double>> environment_options;
  std::shared_ptr<const Environment> custom;
  // Tags at rigid offsets in the body frame (x forward along the direction of travel, y left,
  // z up); the trajectory is the body's. Every tag ranges to every anchor in reach at every epoch.
  std::vector<Eigen::Vector3d> tag_offsets_m = {Eigen::Vector3d::Zero()};
  TunnelOptions tunnel;
  HallOptions hall;
  TrajectoryOptions trajectory;
  RangeModelOptions ranging;

  bool IsValid(std::string* why) const;
  // The most epochs a realization can have: the tunnel at its slowest speed, or the hall's
  // duration, times the rate. A double: it may be astronomically large before validation.
  double MaxEpochs() const;
  int NumAnchors() const { return MakeEnvironment()->NumAnchors(); }
  // The environment the options name (the one place the kind is decided): the caller's, or the
  // tunnel or the hall with their options.
  std::shared_ptr<const sim::Environment> MakeEnvironment() const;
  // Its name in a config: "tunnel", "hall", or the caller's.
  std::string EnvironmentName() const;
};

struct SimAnchor {
  int id = 0;
  Eigen::Vector3d p_world_anchor = Eigen::Vector3d::Zero();
  double bias_m = 0.0;
};

struct SimRange {
  std::size_t epoch = 0;  // index into Scenario::t_s and the tag position tracks
  double t_s = 0.0;
  int tag_id = 0;
  int anchor_id = 0;
  double range_m = 0.0;
  bool is_outlier = false;
};

// One realization: ground truth, what the robot believes about its tag positions, and the range
// stream in time order (tag, then anchor id ascending within one epoch).
struct Scenario {
  std::vector<SimAnchor> anchors;
  std::vector<double> t_s;                        // epochs
  std::vector<Eigen::Vector3d> p_world_body;      // the trajectory
  std::vector<double> yaw_rad;                    // heading: the direction of travel
  // [tag][epoch]; reported = true + one navigation error per epoch (sigma_position_m per axis),
  // shared by the rigidly mounted tags.
  std::vector<std::vector<Eigen::Vector3d>> p_world_tag_true;
  std::vector<std::vector<Eigen::Vector3d>> p_world_tag_reported;
  std::vector<SimRange> ranges;
};

// A realization's anchors (positions and biases), from their own streams.
std::vector<SimAnchor> DrawAnchors(const ScenarioOptions& options, std::uint64_t seed, std::uint64_t realization);
// The body's path of a realization, its kind drawn (Table I's mix of suboptimal runs).
Trajectory DrawBodyPath(const ScenarioOptions& options, const std::vector<SimAnchor>& anchors, std::uint64_t seed,
                        std::uint64_t realization);
// Heading along the direction of travel (central differences; kept while standing still).
std::vector<double> Headings(const std::vector<Eigen::Vector3d>& p_world_body);

// Deterministic in (options, seed, realization); every noise source draws from its own stream.
Scenario GenerateScenario(const ScenarioOptions& options, std::uint64_t seed, std::uint64_t realization);

}  // namespace anchorbench::sim
