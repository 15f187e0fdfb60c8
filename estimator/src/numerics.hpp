#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace anchorbench::estimator::internal {

// A symmetric positive semi-definite normal matrix is treated as singular when the smallest pivot
// of its LDL^T factorization is at most this fraction of the largest: a direction with less than
// 1e-12 of the best-observed direction's information (e.g. collinear tag positions leave one
// with none) would turn round-off into metres. Used by every solver's normal equations.
constexpr double kMinPivotRatio = 1e-12;

// Whether the factorization of a normal matrix is usable (see kMinPivotRatio).
template <typename Matrix>
bool IsWellConditioned(const Eigen::LDLT<Matrix>& ldlt) {
  const auto pivots = ldlt.vectorD();
  if (ldlt.info() != Eigen::Success || !pivots.allFinite()) return false;
  const double largest = pivots.maxCoeff();
  return largest > 0.0 && pivots.minCoeff() > kMinPivotRatio * largest;
}

// Inverse of the 4x4 normal matrix of (p_A, gamma), or false when it is singular.
inline bool InvertNormalMatrix(const Eigen::Matrix4d& normal, Eigen::Matrix4d* inverse) {
  const Eigen::LDLT<Eigen::Matrix4d> ldlt(normal);
  if (!IsWellConditioned(ldlt)) return false;
  *inverse = ldlt.solve(Eigen::Matrix4d::Identity());
  return inverse->allFinite();
}

}  // namespace anchorbench::estimator::internal
