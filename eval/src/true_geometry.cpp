#include "anchorbench/eval/true_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

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

Eigen::Matrix3d TrueGeometry::BiasAwareInformation() const {
  return sum_outer_ - sum_unit_ * sum_unit_.transpose() / count_;  // the Schur complement
}

Eigen::Matrix3d TrueGeometry::BiasAwareInverse() const { return BiasAwareInformation().inverse(); }

double TrueGeometry::BiasAwareLeastInformation() const {
  if (count_ == 0.0) return 0.0;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(BiasAwareInformation(), Eigen::EigenvaluesOnly);
  return std::max(0.0, axes.eigenvalues()(0));
}

double TrueGeometry::BiasAwareHorizontalDop() const {
  if (std::isinf(BiasAwareDop())) return std::numeric_limits<double>::infinity();
  const Eigen::Matrix3d q = BiasAwareInverse();
  return std::sqrt(q(0, 0) + q(1, 1));
}

double TrueGeometry::BiasAwareVerticalDop() const {
  if (std::isinf(BiasAwareDop())) return std::numeric_limits<double>::infinity();
  return std::sqrt(BiasAwareInverse()(2, 2));
}

double TrueGeometry::BiasAwareDop() const { return estimator::BiasAwareDopFromSums(sum_outer_, sum_unit_, count_); }

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
  return estimator::BiasAwareDopAt(p_world_tag, p_world_anchor);
}

}  // namespace anchorbench::eval
