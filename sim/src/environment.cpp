#include "anchorbench/sim/environment.hpp"

#include <algorithm>
#include <cmath>

namespace anchorbench::sim {
namespace {

// Messages name the key first ("length_m must be > 0"), so a config reader can point at it.
bool Fail(std::string* why, const char* message) {
  if (why) *why = message;
  return false;
}

// The keys tunnels and halls share: a box and the anchors on its walls.
template <typename Box>
bool ValidBox(const Box& o, std::string* why) {
  // Up to 100 km: beyond any building or tunnel, and far from where metres lose their centimetres.
  if (!(o.length_m > 0.0 && o.length_m <= 1e5)) return Fail(why, "length_m must be in (0, 1e5]");
  if (!(o.width_m > 0.0 && o.width_m <= 1e5)) return Fail(why, "width_m must be in (0, 1e5]");
  if (!(o.height_m > 0.0 && o.height_m <= 1e5)) return Fail(why, "height_m must be in (0, 1e5]");
  if (o.num_anchors < 1 || o.num_anchors > kMaxAnchors) return Fail(why, "num_anchors must be in [1, 10000]");
  if (!(o.anchor_height_min_m >= 0.0)) return Fail(why, "anchor_height_min_m must be >= 0");
  if (!(o.anchor_height_max_m >= o.anchor_height_min_m && o.anchor_height_max_m <= o.height_m)) {
    return Fail(why, "anchor_height_max_m must be in [anchor_height_min_m, height_m]");
  }
  return true;
}

}  // namespace

bool TunnelOptions::IsValid(std::string* why) const {
  if (!ValidBox(*this, why)) return false;
  if (!(along_jitter_m >= 0.0 && along_jitter_m <= length_m)) return Fail(why, "along_jitter_m must be in [0, length_m]");
  return true;
}

bool HallOptions::IsValid(std::string* why) const { return ValidBox(*this, why); }

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
