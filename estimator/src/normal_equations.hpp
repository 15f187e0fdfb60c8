#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace anchorbench::estimator::internal {

// Inverse of the 4x4 normal matrix N of (p_A, gamma), or false when N is numerically singular:
// the pivoted LDL^T factorization's smallest pivot is <= 1e-12 of its largest (e.g. collinear tag
// positions leave a direction with no information).
inline bool InvertNormalMatrix(const Eigen::Matrix4d& normal, Eigen::Matrix4d* inverse) {
  const Eigen::LDLT<Eigen::Matrix4d> ldlt(normal);
  const Eigen::Vector4d pivots = ldlt.vectorD();
  const double largest = pivots.maxCoeff();
  if (ldlt.info() != Eigen::Success || !(largest > 0.0) || !std::isfinite(largest) ||
      !(pivots.minCoeff() > 1e-12 * largest)) {
    return false;
  }
  *inverse = ldlt.solve(Eigen::Matrix4d::Identity());
  return inverse->allFinite();
}

}  // namespace anchorbench::estimator::internal
