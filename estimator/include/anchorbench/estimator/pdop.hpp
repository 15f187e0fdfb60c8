#pragma once

#include <cmath>
#include <limits>
#include <span>

#include <Eigen/Core>

namespace anchorbench::estimator {

// PDOP is +infinity when det(I) <= this times trace(I)^3: a direction with almost no information
// (e.g. collinear tag positions leave one with none) would turn round-off into metres. The idea
// of the solvers' kMinPivotRatio, for 3x3 matrices inverted in closed form, not factorized.
inline constexpr double kMinRelativeDeterminant = 1e-13;

// sqrt(tr(I^-1)) (Eq. (2)) for a symmetric 3x3 information matrix given by its upper triangle;
// +infinity when it is numerically singular. Inline: the streaming PDOP calls it per sample.
inline double PdopFromUpperTriangle(double m00, double m01, double m02, double m11, double m12,
                                    double m22) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // tr(I^-1) = (sum of the principal 2x2 minors) / det(I) for a symmetric 3x3 matrix.
  const double minor_00 = m11 * m22 - m12 * m12;
  const double minor_11 = m00 * m22 - m02 * m02;
  const double minor_22 = m00 * m11 - m01 * m01;
  const double det = m00 * minor_00 - m01 * (m01 * m22 - m12 * m02) + m02 * (m01 * m12 - m11 * m02);
  const double trace = m00 + m11 + m22;
  if (!(trace > 0.0) || !(det > kMinRelativeDeterminant * trace * trace * trace)) return kInf;
  const double trace_of_inverse = (minor_00 + minor_11 + minor_22) / det;
  if (!(trace_of_inverse > 0.0) || !(trace_of_inverse < kInf)) return kInf;
  return std::sqrt(trace_of_inverse);
}

// sqrt(tr(B^-1)) for the symmetric 2x2 x-y block B of an information matrix: the horizontal DOP
// with the height known. +infinity when B is numerically singular (the test of the 3x3 case).
inline double HdopFromBlock(double m00, double m01, double m11) {
  const double det = m00 * m11 - m01 * m01;
  const double trace = m00 + m11;
  if (!(trace > 0.0) || !(det > kMinRelativeDeterminant * trace * trace)) return std::numeric_limits<double>::infinity();
  return std::sqrt(trace / det);
}

// The same for a full matrix; only its upper triangle is read.
inline double PdopFromInformation(const Eigen::Matrix3d& m) {
  return PdopFromUpperTriangle(m(0, 0), m(0, 1), m(0, 2), m(1, 1), m(1, 2), m(2, 2));
}

// The bias-aware DOP from the sums of a geometry matrix's rows g_k over n rows: with the bias
// estimated too, H = [G | 1], and the position block of (H^T H)^-1 is the inverse of the Schur
// complement sum g g^T - (sum g)(sum g)^T / n (the spread of the rows about their mean). Its root
// trace is >= the 3-column PDOP; +infinity where that one is already singular (the relative rank
// test would otherwise judge the two matrices against different scales) or n < 2.
inline double BiasAwareDopFromSums(const Eigen::Matrix3d& sum_outer, const Eigen::Vector3d& sum_rows, double n) {
  if (n < 2.0 || std::isinf(PdopFromInformation(sum_outer))) return std::numeric_limits<double>::infinity();
  return PdopFromInformation(sum_outer - sum_rows * sum_rows.transpose() / n);
}

// The bias-aware DOP of the unit directions from a point to the tags (the true anchor in
// evaluation, an estimate or a point of its confidence region online). O(N).
double BiasAwareDopAt(std::span<const Eigen::Vector3d> p_world_tag, const Eigen::Vector3d& p_world_anchor);

// Eq. (2)-(3): PDOP with rows (p_k - p_A)^T / d_k for a given anchor position and ranges.
// With an estimated p_A this is the "LS PDOP" / "NLS PDOP" of Sec. IV-B.
double GeometryPdop(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                    const Eigen::Vector3d& p_world_anchor);

}  // namespace anchorbench::estimator
