#pragma once

#include <Eigen/Core>

namespace anchorbench::estimator {

// One UWB range with the tag position interpolated at its timestamp (Sec. III-A).
struct RangeSample {
  double t_s = 0.0;
  int tag_id = 0;
  int anchor_id = 0;
  double range_m = 0.0;
  Eigen::Vector3d p_world_tag = Eigen::Vector3d::Zero();
};

}  // namespace anchorbench::estimator
