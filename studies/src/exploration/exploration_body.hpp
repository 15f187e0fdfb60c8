#pragma once
// The exploration study's robot body (studies/exploration.hpp): internal to the engine.

#include <cmath>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace anchorbench::studies {

// The body over one run: the pattern back and forth, or a route away from it (one candidate, or
// planned waypoints) with a dwell at each of its places, and back to where it left the pattern
// (a new route may start on the way back: detours chain without the return between them).
// One Step() per epoch.
class Body {
 public:
  Body(const std::vector<Eigen::Vector3d>& pattern, double step_m) : pattern_(pattern), step_m_(step_m), p_(pattern.front()) {}

  const Eigen::Vector3d& p_world_body() const { return p_; }
  double yaw_rad() const { return yaw_rad_; }
  double distance_m() const { return distance_m_; }
  bool on_pattern() const { return leg_ == Leg::kPattern; }
  // On the pattern or on the way back to it: free to take another route.
  bool free() const { return leg_ == Leg::kPattern || leg_ == Leg::kBack; }
  bool dwelling() const { return leg_ == Leg::kDwell; }

  // Cuts the dwell at the current place short: on to the route's next place, or back.
  void Leave() {
    if (leg_ == Leg::kDwell) leg_ = ++next_ < targets_.size() ? Leg::kOut : Leg::kBack;
  }

  void Visit(std::vector<Eigen::Vector3d> p_world_targets, int dwell_epochs) {
    if (p_world_targets.empty()) return;
    targets_ = std::move(p_world_targets);
    next_ = 0;
    dwell_per_target_ = dwell_epochs;
    leg_ = Leg::kOut;
  }

  void Step() {
    const Eigen::Vector3d p_before = p_;
    switch (leg_) {
      case Leg::kPattern: AlongPattern(); break;
      case Leg::kOut:
        if (Toward(targets_[next_])) {
          leg_ = Leg::kDwell;
          dwell_epochs_ = dwell_per_target_;
        }
        break;
      case Leg::kDwell:
        if (--dwell_epochs_ <= 0) Leave();
        break;
      case Leg::kBack:
        if (Toward(pattern_[index_])) leg_ = Leg::kPattern;
        break;
    }
    const Eigen::Vector3d step = p_ - p_before;
    distance_m_ += step.norm();
    if (step.head<2>().norm() > 1e-9) yaw_rad_ = std::atan2(step.y(), step.x());
  }

 private:
  enum class Leg { kPattern, kOut, kDwell, kBack };

  void AlongPattern() {
    if (pattern_.size() < 2) return;
    const long next = static_cast<long>(index_) + direction_;
    if (next < 0 || next >= static_cast<long>(pattern_.size())) direction_ = -direction_;  // back the way it came
    index_ = static_cast<std::size_t>(static_cast<long>(index_) + direction_);
    p_ = pattern_[index_];
  }

  // One step of step_m_ toward `p_world_target`; true once there.
  bool Toward(const Eigen::Vector3d& p_world_target) {
    const Eigen::Vector3d to = p_world_target - p_;
    if (to.norm() <= step_m_) {
      p_ = p_world_target;
      return true;
    }
    p_ += step_m_ * to.normalized();
    return false;
  }

  const std::vector<Eigen::Vector3d>& pattern_;
  double step_m_;
  Eigen::Vector3d p_;
  std::vector<Eigen::Vector3d> targets_;
  std::size_t next_ = 0;
  int dwell_per_target_ = 0;
  std::size_t index_ = 0;
  int direction_ = 1;
  int dwell_epochs_ = 0;
  Leg leg_ = Leg::kPattern;
  double yaw_rad_ = 0.0;
  double distance_m_ = 0.0;
};

}  // namespace anchorbench::studies
