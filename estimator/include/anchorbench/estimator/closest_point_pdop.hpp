#pragma once

#include <Eigen/Core>

namespace anchorbench::estimator {

// Closest-point-to-anchor PDOP of Sec. III-C, Eq. (4), maintained in O(1) per sample.
//
// With w_k = 1/d_k^2 and the running sums S0 = sum w_k, S1 = sum w_k p_k, S2 = sum w_k p_k p_k^T,
//   G~^T G~ = sum_k w_k (p_k - p_C)(p_k - p_C)^T = S2 - S1 p_C^T - p_C S1^T + S0 p_C p_C^T   (Eq. (6))
// where p_C is the tag position of the shortest range so far. The row of p_C itself contributes
// zero, so it need not be removed from the sums. Positions are stored relative to the first
// sample so the sums do not cancel far from the world origin.
class ClosestPointPdop {
 public:
  void Add(const Eigen::Vector3d& p_world_tag, double range_m);

  // PDOP = sqrt(tr((G~^T G~)^-1)) (Eq. (2) with G~). +infinity with fewer than 4 samples
  // (G~ has N-1 rows) or when G~^T G~ is numerically rank-deficient; never NaN.
  double Value() const;

  // G~^T G~ of Eq. (6).
  Eigen::Matrix3d Information() const;

  int count() const { return count_; }
  Eigen::Vector3d p_world_closest() const { return origin_ + p_closest_; }

 private:
  int count_ = 0;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  double s0_ = 0.0;
  Eigen::Vector3d s1_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d s2_ = Eigen::Matrix3d::Zero();
  Eigen::Vector3d p_closest_ = Eigen::Vector3d::Zero();  // relative to origin_
  double min_range_m_ = 0.0;
};

}  // namespace anchorbench::estimator
