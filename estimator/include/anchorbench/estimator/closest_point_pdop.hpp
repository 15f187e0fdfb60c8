#pragma once

#include <limits>

#include <Eigen/Core>

#include "anchorbench/estimator/pdop.hpp"

namespace anchorbench::estimator {

// Closest-point-to-anchor PDOP of Sec. III-C, Eq. (4), maintained in O(1) per sample.
//
// With w_k = 1/d_k^2 and p_C the tag position of the shortest range so far, the sums
//   S0 = sum w_k,  S1 = sum w_k (p_k - p_C),  S2 = sum w_k (p_k - p_C)(p_k - p_C)^T = G~^T G~
// are kept about p_C itself, so the PDOP reads S2 directly. When a shorter range moves p_C by
// delta, Eq. (6)'s expansion re-centres them in O(1):
//   S2 <- S2 - S1 delta^T - delta S1^T + S0 delta delta^T,   S1 <- S1 - S0 delta.
// The row of p_C itself contributes zero, so it need not be removed. S2 is symmetric: only its
// upper triangle (00, 01, 02, 11, 12, 22) is kept. Add and Value are inline: the initializer
// calls both on every sample.
//
// With the bias as a fourth column of ones (our extension, for the dop4_closest_point trigger),
// the bias-aware DOP also needs the sum of the rows g_k = (p_k - p_C)/d_k themselves:
//   T0 = sum 1/d_k,  T1 = sum (p_k - p_C)/d_k,  re-centred as T1 <- T1 - T0 delta.
class ClosestPointPdop {
 public:
  using Upper = Eigen::Matrix<double, 6, 1>;

  void Add(const Eigen::Vector3d& p_world_tag, double range_m) {
    if (count_ == 0) {
      p_world_closest_ = p_world_tag;
      min_range_m_ = range_m;
    } else if (range_m < min_range_m_) {
      Recentre(p_world_tag - p_world_closest_);
      p_world_closest_ = p_world_tag;
      min_range_m_ = range_m;
    }
    const Eigen::Vector3d p = p_world_tag - p_world_closest_;
    const double w = 1.0 / (range_m * range_m);  // row scaling 1/d_k of Eq. (4), squared
    const Eigen::Vector3d wp = w * p;
    s0_ += w;
    s1_ += wp;
    s2_ += Outer(wp, p);
    const double v = 1.0 / range_m;
    t0_ += v;
    t1_ += v * p;
    ++count_;
  }

  // PDOP = sqrt(tr((G~^T G~)^-1)) (Eq. (2) with G~). +infinity with fewer than 4 samples
  // (G~ has N-1 rows) or when G~^T G~ is numerically rank-deficient; never NaN.
  double Value() const {
    if (count_ < 4) return std::numeric_limits<double>::infinity();  // G~ needs >= 3 rows
    return PdopFromUpperTriangle(s2_[0], s2_[1], s2_[2], s2_[3], s2_[4], s2_[5]);
  }

  // The bias-aware DOP of G~ with a column of ones (BiasAwareDopFromSums); +inf as Value().
  double BiasAwareValue() const;

  // The DOP of x-y with the height known (ours, for a height prior on a flat path):
  // sqrt(tr(B^-1)) of the x-y block B of G~^T G~; +inf as Value().
  double HorizontalValue() const;

  // G~^T G~ of Eq. (6).
  Eigen::Matrix3d Information() const;

  int count() const { return count_; }
  const Eigen::Vector3d& p_world_closest() const { return p_world_closest_; }

 private:
  static Upper Outer(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return Upper(a.x() * b.x(), a.x() * b.y(), a.x() * b.z(), a.y() * b.y(), a.y() * b.z(),
                 a.z() * b.z());
  }

  // The sums about p_C + delta instead of p_C: with q = S0 delta - S1,
  // S2_ij - S1_i delta_j - delta_i S1_j + S0 delta_i delta_j = S2_ij - S1_i delta_j + delta_i q_j.
  void Recentre(const Eigen::Vector3d& delta) {
    const Eigen::Vector3d q = s0_ * delta - s1_;
    const auto entry = [&](int i, int j) { return -s1_[i] * delta[j] + delta[i] * q[j]; };
    s2_ += Upper(entry(0, 0), entry(0, 1), entry(0, 2), entry(1, 1), entry(1, 2), entry(2, 2));
    s1_ = -q;
    t1_ -= t0_ * delta;
  }

  int count_ = 0;
  double s0_ = 0.0;
  Eigen::Vector3d s1_ = Eigen::Vector3d::Zero();
  Upper s2_ = Upper::Zero();
  double t0_ = 0.0;
  Eigen::Vector3d t1_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_world_closest_ = Eigen::Vector3d::Zero();
  double min_range_m_ = 0.0;
};

}  // namespace anchorbench::estimator
