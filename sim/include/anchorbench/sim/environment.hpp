#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/estimator/enum_names.hpp"
#include "anchorbench/sim/random_stream.hpp"

namespace anchorbench::sim {

constexpr int kMaxAnchors = 10000;  // per environment (random sub-stream keys: scenario.hpp)

// Tunnel frame: x along the tunnel in [0, length], y across in [-width/2, width/2], z up from the
// floor in [0, height]. Anchors are spread evenly along the whole length (Sec. IV-A) with a
// random jitter, cycling left wall -> right wall -> ceiling; wall anchors get a random height.
struct TunnelOptions {
  double length_m = 300.0;
  double width_m = 8.0;
  double height_m = 6.0;
  int num_anchors = 30;
  double anchor_height_min_m = 1.0;  // wall anchors: uniform in [min, max]
  double anchor_height_max_m = 5.0;
  double along_jitter_m = 2.0;       // uniform +- jitter of each anchor's x around its slot

  bool IsValid(std::string* why) const;
};

enum class HallWalls {
  kAll,    // evenly spaced around the perimeter
  kFront,  // evenly spaced along the front wall (y = 0), e.g. in front of a machine hall
};
inline constexpr estimator::EnumNames<HallWalls, 2> kHallWallsNames({
    {HallWalls::kAll, "all"}, {HallWalls::kFront, "front"}});
inline std::string_view ToString(HallWalls value) { return kHallWallsNames.Name(value); }
inline bool ParseHallWalls(std::string_view name, HallWalls* value) { return kHallWallsNames.Parse(name, value); }

// Hall frame: a box [0, length] x [0, width] x [0, height]; anchors on its walls, heights
// uniform in [min, max].
struct HallOptions {
  double length_m = 40.0;
  double width_m = 20.0;
  double height_m = 8.0;
  int num_anchors = 8;
  double anchor_height_min_m = 1.0;
  double anchor_height_max_m = 4.0;
  HallWalls anchor_walls = HallWalls::kAll;

  bool IsValid(std::string* why) const;
};

}  // namespace anchorbench::sim
