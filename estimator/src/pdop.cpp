#include "anchorbench/estimator/pdop.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Core>

namespace anchorbench::estimator {

double PdopFromInformation(const Eigen::Matrix3d& information) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // tr(I^-1) = (sum of the principal 2x2 minors) / det(I) for a symmetric 3x3 matrix.
  const Eigen::Matrix3d& m = information;
  const double minor_00 = m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1);
  const double minor_11 = m(0, 0) * m(2, 2) - m(0, 2) * m(2, 0);
  const double minor_22 = m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
  const double det = m(0, 0) * minor_00 - m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
                     m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
  const double trace = m.trace();
  // Rank-deficient (e.g. collinear tag positions): det vanishes relative to the scale trace^3.
  if (!(trace > 0.0) || !(det > 1e-13 * trace * trace * trace)) return kInf;
  const double trace_of_inverse = (minor_00 + minor_11 + minor_22) / det;
  if (!(trace_of_inverse > 0.0) || !std::isfinite(trace_of_inverse)) return kInf;
  return std::sqrt(trace_of_inverse);  // Eq. (2)
}

double GeometryPdop(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                    const Eigen::Vector3d& p_world_anchor) {
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
  for (std::size_t k = 0; k < p_world_tag.size(); ++k) {
    const Eigen::Vector3d row = (p_world_tag[k] - p_world_anchor) / range_m[k];  // Eq. (3)
    information += row * row.transpose();                                      // Eq. (5)
  }
  return PdopFromInformation(information);
}

void TrueGeometry::Add(const Eigen::Vector3d& p_world_tag) {
  const Eigen::Vector3d diff = p_world_tag - p_world_anchor_;
  const double distance_m = diff.norm();
  if (distance_m <= 0.0) return;  // a tag exactly at the anchor has no direction
  const Eigen::Vector3d unit = diff / distance_m;
  sum_outer_ += unit * unit.transpose();
  sum_unit_ += unit;
  count_ += 1.0;
}

double TrueGeometry::Pdop() const { return PdopFromInformation(sum_outer_); }

double TrueGeometry::BiasAwareDop() const {
  // It is >= the 3-column PDOP; where that one is already singular, so is this one (the relative
  // rank test would otherwise judge the two matrices against different scales).
  if (count_ < 2.0 || std::isinf(Pdop())) return std::numeric_limits<double>::infinity();
  // sum (u - u_mean)(u - u_mean)^T = sum u u^T - (sum u)(sum u)^T / n
  return PdopFromInformation(sum_outer_ - sum_unit_ * sum_unit_.transpose() / count_);
}

namespace {

TrueGeometry Accumulate(std::span<const Eigen::Vector3d> p_world_tag, const Eigen::Vector3d& p_world_anchor) {
  TrueGeometry geometry(p_world_anchor);
  for (const Eigen::Vector3d& p : p_world_tag) geometry.Add(p);
  return geometry;
}

}  // namespace

double TruePdop(std::span<const Eigen::Vector3d> p_world_tag, const Eigen::Vector3d& p_world_anchor) {
  return Accumulate(p_world_tag, p_world_anchor).Pdop();
}

double BiasAwareDop(std::span<const Eigen::Vector3d> p_world_tag, const Eigen::Vector3d& p_world_anchor) {
  return Accumulate(p_world_tag, p_world_anchor).BiasAwareDop();
}

}  // namespace anchorbench::estimator
