#include "anchorbench/eval/true_geometry.hpp"

#include <cmath>
#include <limits>

#include "anchorbench/estimator/pdop.hpp"

namespace anchorbench::eval {

using estimator::PdopFromInformation;

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

}  // namespace anchorbench::eval
