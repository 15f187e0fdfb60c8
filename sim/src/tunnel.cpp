// The tunnel of Sec. IV-A: anchors spread along its whole length, a body travelling from one end
// towards the other (trajectory.cpp's TunnelTrajectory).
#include <algorithm>

#include "anchorbench/sim/environment_model.hpp"

namespace anchorbench::sim {
namespace {

std::vector<Eigen::Vector3d> TunnelAnchors(const TunnelOptions& o, RandomStream& layout) {
  std::vector<Eigen::Vector3d> anchors;
  anchors.reserve(o.num_anchors);
  const double slot_m = o.length_m / o.num_anchors;
  const double half_width = 0.5 * o.width_m;
  for (int i = 0; i < o.num_anchors; ++i) {
    const double x = std::clamp((i + 0.5) * slot_m + layout.Uniform(-o.along_jitter_m, o.along_jitter_m), 0.0,
                                o.length_m);
    const double wall_height = layout.Uniform(o.anchor_height_min_m, o.anchor_height_max_m);
    const double ceiling_y = layout.Uniform(-0.8 * half_width, 0.8 * half_width);
    switch (i % 3) {
      case 0: anchors.emplace_back(x, half_width, wall_height); break;   // left wall
      case 1: anchors.emplace_back(x, -half_width, wall_height); break;  // right wall
      default: anchors.emplace_back(x, ceiling_y, o.height_m); break;    // ceiling
    }
  }
  return anchors;
}

class Tunnel : public Environment {
 public:
  explicit Tunnel(const TunnelOptions& options) : o_(options) {}

  bool IsValid(const TrajectoryOptions& trajectory, std::string* why) const override {
    if (trajectory.kind == TrajectoryKind::kApproach) {
      if (why) *why = "trajectory.kind approach is a hall trajectory (the tunnel has none)";
      return false;
    }
    return o_.IsValid(why);
  }
  int NumAnchors() const override { return o_.num_anchors; }
  std::vector<Eigen::Vector3d> Anchors(RandomStream& layout) const override { return TunnelAnchors(o_, layout); }
  Trajectory Path(const TrajectoryOptions& trajectory, std::span<const Eigen::Vector3d>,
                  RandomStream& shape) const override {
    return TunnelTrajectory(o_, trajectory, shape);
  }
  // The whole length at the slowest speed.
  double LongestRun_s(const TrajectoryOptions& t) const override {
    return o_.length_m / (t.speed_mps * (1.0 - t.speed_variation));
  }
  Box Bounds() const override {
    return {Eigen::Vector3d(0.0, -0.5 * o_.width_m, 0.0), Eigen::Vector3d(o_.length_m, 0.5 * o_.width_m, o_.height_m)};
  }

 private:
  TunnelOptions o_;
};

}  // namespace

std::unique_ptr<Environment> MakeTunnel(const TunnelOptions& options) { return std::make_unique<Tunnel>(options); }

}  // namespace anchorbench::sim
