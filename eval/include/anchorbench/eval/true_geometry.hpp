#pragma once

#include <span>

#include <Eigen/Core>

namespace anchorbench::eval {

// True PDOP for evaluation: Eq. (3) at the true anchor with the true distances, so every row is
// the unit vector from the anchor to the tag.
double TruePdop(std::span<const Eigen::Vector3d> p_world_tag, const Eigen::Vector3d& p_world_anchor);

// Bias-aware DOP: with the bias gamma estimated too, H = [G | 1] and the anchor-position block of
// (H^T H)^-1 is (sum_k (u_k - u_mean)(u_k - u_mean)^T)^-1 (Schur complement), u_k the unit rows.
// sigma_d times its root trace is the Cramer-Rao bound on the position error of (p_A, gamma);
// it is always >= TruePdop, since only the spread of the viewing directions counts.
double BiasAwareDop(std::span<const Eigen::Vector3d> p_world_tag, const Eigen::Vector3d& p_world_anchor);

// Both, one sample at a time in O(1), for a known anchor: running sums of the unit vectors u_k
// from the anchor to the tags.
class TrueGeometry {
 public:
  explicit TrueGeometry(const Eigen::Vector3d& p_world_anchor) : p_world_anchor_(p_world_anchor) {}
  void Add(const Eigen::Vector3d& p_world_tag);
  double Pdop() const;          // TruePdop of the samples so far
  double BiasAwareDop() const;  // BiasAwareDop of the samples so far
  // BiasAwareDop split: sqrt(Q_xx + Q_yy) and sqrt(Q_zz) of its position block Q, so that
  // DOP^2 = HDOP^2 + VDOP^2 (both +inf where it is). On a flat path the height trades off against
  // the bias (the rows' vertical parts barely vary): a large VDOP.
  double BiasAwareHorizontalDop() const;
  double BiasAwareVerticalDop() const;
  // The smallest eigenvalue of the bias-aware information of the position, sum (u - u_mean)(u -
  // u_mean)^T (per sigma^-2): 1 / lambda_max of BiasAwareDop's Q, and 0, not a NaN, where Q is singular.
  double BiasAwareLeastInformation() const;

 private:
  Eigen::Matrix3d BiasAwareInformation() const;  // sum (u - u_mean)(u - u_mean)^T: of the position, the bias estimated
  Eigen::Matrix3d BiasAwareInverse() const;      // its inverse, the position block of (H^T H)^-1, H = [G | 1]

  Eigen::Vector3d p_world_anchor_;
  Eigen::Matrix3d sum_outer_ = Eigen::Matrix3d::Zero();  // sum u u^T
  Eigen::Vector3d sum_unit_ = Eigen::Vector3d::Zero();   // sum u
  double count_ = 0.0;
};

}  // namespace anchorbench::eval
