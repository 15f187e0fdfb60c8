#pragma once

#include <Eigen/Core>

namespace anchorbench::estimator {

// The range residual of Eq. (11), r_k = ||p_A - p_k|| + gamma - d_k: how much longer the model
// (true distance plus the anchor's bias) is than the measured range. Every solver, RANSAC's
// consensus and the alpha search use this one definition.
inline double RangeResidual(const Eigen::Vector3d& p_world_anchor, double bias_m, const Eigen::Vector3d& p_world_tag,
                            double range_m) {
  return (p_world_anchor - p_world_tag).norm() + bias_m - range_m;
}

// The same for theta = (p_A, gamma), with its Jacobian row dr_k/dtheta = [(p_A - p_k)^T / ||p_A - p_k||, 1].
// With the anchor exactly on the tag the direction is undefined; its part of the row is zero.
inline double RangeResidual(const Eigen::Vector4d& theta, const Eigen::Vector3d& p_world_tag, double range_m,
                            Eigen::Vector4d* jacobian) {
  const Eigen::Vector3d diff = theta.head<3>() - p_world_tag;
  const double distance_m = diff.norm();
  if (distance_m > 1e-12) {
    jacobian->head<3>() = diff / distance_m;
  } else {
    jacobian->head<3>().setZero();
  }
  (*jacobian)(3) = 1.0;
  return distance_m + theta(3) - range_m;
}

}  // namespace anchorbench::estimator
