#pragma once
// What a simulated environment is to a scenario: where its anchors go, how a body moves through
// it, how long a run can last, and the box it may move in. The tunnel (tunnel.cpp) and the hall
// (hall.cpp) are one file each; ScenarioOptions::MakeEnvironment() makes the one its config names.

#include <memory>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/sim/environment.hpp"
#include "anchorbench/sim/random_stream.hpp"
#include "anchorbench/sim/trajectory.hpp"

namespace anchorbench::sim {

class Environment {
 public:
  struct Box {
    Eigen::Vector3d low = Eigen::Vector3d::Zero();
    Eigen::Vector3d high = Eigen::Vector3d::Zero();
  };

  virtual ~Environment() = default;

  // Its options' own limits, and whether it has a path of `trajectory`'s kinds; *why names the
  // key first ("length_m must be > 0").
  virtual bool IsValid(const TrajectoryOptions& trajectory, std::string* why) const = 0;
  virtual int NumAnchors() const = 0;
  // The anchors' positions, drawn from the realization's layout stream.
  virtual std::vector<Eigen::Vector3d> Anchors(RandomStream& layout) const = 0;
  // The body's path of the kind already drawn (trajectory.kind), from the realization's shape
  // stream; some paths head for an anchor (the hall's approach).
  virtual Trajectory Path(const TrajectoryOptions& trajectory, std::span<const Eigen::Vector3d> p_world_anchors,
                          RandomStream& shape) const = 0;
  // The longest run a path can last (s): what bounds a realization's size before it is drawn.
  virtual double LongestRun_s(const TrajectoryOptions& trajectory) const = 0;
  // The space a body may move in (a guided detour's bounds).
  virtual Box Bounds() const = 0;
};

std::unique_ptr<Environment> MakeTunnel(const TunnelOptions& options);  // tunnel.cpp
std::unique_ptr<Environment> MakeHall(const HallOptions& options);      // hall.cpp

}  // namespace anchorbench::sim
