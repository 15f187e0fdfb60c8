#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/sim/environment.hpp"
#include "anchorbench/sim/range_model.hpp"
#include "anchorbench/sim/trajectory.hpp"

namespace anchorbench::sim {

enum class EnvironmentKind { kTunnel, kHall };
std::string_view ToString(EnvironmentKind kind);
bool ParseEnvironmentKind(std::string_view name, EnvironmentKind* kind);

struct ScenarioOptions {
  EnvironmentKind environment = EnvironmentKind::kTunnel;
  TunnelOptions tunnel;
  HallOptions hall;
  TrajectoryOptions trajectory;
  RangeModelOptions ranging;

  bool IsValid(std::string* why) const;
};

struct SimAnchor {
  int id = 0;
  Eigen::Vector3d p_world_anchor = Eigen::Vector3d::Zero();
  double bias_m = 0.0;
};

struct SimRange {
  double t_s = 0.0;
  int tag_id = 0;
  int anchor_id = 0;
  double range_m = 0.0;
  bool is_outlier = false;
};

// One realization: ground truth, what the robot believes about its tag positions, and the range
// stream in time order (anchor id ascending within one epoch).
struct Scenario {
  TrajectoryKind trajectory_kind = TrajectoryKind::kRandom;  // as drawn for this realization
  std::vector<SimAnchor> anchors;
  std::vector<double> t_s;                            // epochs (one tag, id 0)
  std::vector<Eigen::Vector3d> p_world_tag_true;
  std::vector<Eigen::Vector3d> p_world_tag_reported;  // true + sigma_position_m noise
  std::vector<SimRange> ranges;
};

// Deterministic in (options, seed, realization); every noise source draws from its own stream.
Scenario GenerateScenario(const ScenarioOptions& options, std::uint64_t seed, std::uint64_t realization);

}  // namespace anchorbench::sim
