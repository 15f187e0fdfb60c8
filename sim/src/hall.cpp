// A hall: anchors on its walls (all around, or along the front), a body wandering inside it, or
// approaching anchor 0 inside a narrow cone first (trajectory.cpp's HallTrajectory and
// ApproachTrajectory).
#include <cmath>

#include "anchorbench/sim/environment_model.hpp"

namespace anchorbench::sim {
namespace {

std::vector<Eigen::Vector3d> HallAnchors(const HallOptions& o, RandomStream& layout) {
  std::vector<Eigen::Vector3d> anchors;
  anchors.reserve(o.num_anchors);
  if (o.anchor_walls == HallWalls::kFront) {
    for (int i = 0; i < o.num_anchors; ++i) {
      anchors.emplace_back((i + 0.5) * o.length_m / o.num_anchors, 0.0,
                           layout.Uniform(o.anchor_height_min_m, o.anchor_height_max_m));
    }
    return anchors;
  }
  const double perimeter = 2.0 * (o.length_m + o.width_m);
  const double offset = layout.Uniform(0.0, perimeter / o.num_anchors);
  for (int i = 0; i < o.num_anchors; ++i) {
    double s = std::fmod(offset + i * perimeter / o.num_anchors, perimeter);
    const double z = layout.Uniform(o.anchor_height_min_m, o.anchor_height_max_m);
    if (s < o.length_m) {
      anchors.emplace_back(s, 0.0, z);
    } else if ((s -= o.length_m) < o.width_m) {
      anchors.emplace_back(o.length_m, s, z);
    } else if ((s -= o.width_m) < o.length_m) {
      anchors.emplace_back(o.length_m - s, o.width_m, z);
    } else {
      anchors.emplace_back(0.0, o.width_m - (s - o.length_m), z);
    }
  }
  return anchors;
}

class Hall : public Environment {
 public:
  explicit Hall(const HallOptions& options) : o_(options) {}

  bool IsValid(const TrajectoryOptions&, std::string* why) const override { return o_.IsValid(why); }
  int NumAnchors() const override { return o_.num_anchors; }
  std::vector<Eigen::Vector3d> Anchors(RandomStream& layout) const override { return HallAnchors(o_, layout); }
  Trajectory Path(const TrajectoryOptions& trajectory, std::span<const Eigen::Vector3d> p_world_anchors,
                  RandomStream& shape) const override {
    if (trajectory.kind == TrajectoryKind::kApproach) {
      return ApproachTrajectory(o_, trajectory, p_world_anchors.front(), shape);
    }
    return HallTrajectory(o_, trajectory, shape);
  }
  double LongestRun_s(const TrajectoryOptions& t) const override { return t.hall_duration_s; }
  Box Bounds() const override { return {Eigen::Vector3d::Zero(), Eigen::Vector3d(o_.length_m, o_.width_m, o_.height_m)}; }

 private:
  HallOptions o_;
};

}  // namespace

std::unique_ptr<Environment> MakeHall(const HallOptions& options) { return std::make_unique<Hall>(options); }

}  // namespace anchorbench::sim
