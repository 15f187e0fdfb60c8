#include "anchorbench/sim/environment.hpp"

#include <algorithm>
#include <cmath>

namespace anchorbench::sim {
namespace {

bool Fail(std::string* why, const char* message) {
  if (why) *why = message;
  return false;
}

bool ValidHeights(double min_m, double max_m, double height_m) {
  return min_m >= 0.0 && min_m <= max_m && max_m <= height_m;
}

}  // namespace

bool TunnelOptions::IsValid(std::string* why) const {
  if (!(length_m > 0.0 && width_m > 0.0 && height_m > 0.0)) return Fail(why, "tunnel dimensions must be > 0");
  if (num_anchors < 1) return Fail(why, "num_anchors must be >= 1");
  if (!ValidHeights(anchor_height_min_m, anchor_height_max_m, height_m))
    return Fail(why, "anchor heights must satisfy 0 <= min <= max <= height_m");
  if (!(along_jitter_m >= 0.0)) return Fail(why, "along_jitter_m must be >= 0");
  return true;
}

bool HallOptions::IsValid(std::string* why) const {
  if (!(length_m > 0.0 && width_m > 0.0 && height_m > 0.0)) return Fail(why, "hall dimensions must be > 0");
  if (num_anchors < 1) return Fail(why, "num_anchors must be >= 1");
  if (!ValidHeights(anchor_height_min_m, anchor_height_max_m, height_m))
    return Fail(why, "anchor heights must satisfy 0 <= min <= max <= height_m");
  return true;
}

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

std::string_view ToString(HallWalls walls) { return walls == HallWalls::kAll ? "all" : "front"; }

bool ParseHallWalls(std::string_view name, HallWalls* walls) {
  if (name == "all") *walls = HallWalls::kAll;
  else if (name == "front") *walls = HallWalls::kFront;
  else return false;
  return true;
}

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

}  // namespace anchorbench::sim
