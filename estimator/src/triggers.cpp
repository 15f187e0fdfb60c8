#include "anchorbench/estimator/triggers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "anchorbench/estimator/pdop.hpp"

namespace anchorbench::estimator {

bool EstimatePdopTrigger::Evaluate(const TriggerInput& in) {
  const SolveResult estimate = solver_->Solve(in.p_world_tag, in.range_m);
  return Succeeded(estimate.status) && GeometryPdop(in.p_world_tag, in.range_m, estimate.p_world_anchor) < threshold_;
}

double WorstBiasAwareDop(std::span<const Eigen::Vector3d> p_world_tag, const SolveResult& estimate, double sigmas) {
  const Eigen::Matrix3d covariance = estimate.covariance.topLeftCorner<3, 3>();
  if (!covariance.allFinite()) return std::numeric_limits<double>::infinity();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(covariance);
  double worst = BiasAwareDopAt(p_world_tag, estimate.p_world_anchor);
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d half_axis = sigmas * std::sqrt(std::max(axes.eigenvalues()(i), 0.0)) * axes.eigenvectors().col(i);
    for (const double side : {-1.0, 1.0}) {
      worst = std::max(worst, BiasAwareDopAt(p_world_tag, estimate.p_world_anchor + side * half_axis));
    }
  }
  return worst;
}

bool ConfidenceRegionDopTrigger::Evaluate(const TriggerInput& in) {
  const SolveResult estimate = solver_->Solve(in.p_world_tag, in.range_m);
  return Succeeded(estimate.status) && WorstBiasAwareDop(in.p_world_tag, estimate, sigmas_) < threshold_;
}

}  // namespace anchorbench::estimator
