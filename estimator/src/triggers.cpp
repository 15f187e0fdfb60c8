#include "anchorbench/estimator/triggers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "anchorbench/estimator/pdop.hpp"

namespace anchorbench::estimator {

namespace {

// Why a solving trigger's failed solve holds the anchor back: `mirror` from the mirror check (its
// numbers), `solve` for any other failure.
Judgement FailedSolveJudgement(const TriggerInput& in, const SolveResult& estimate) {
  if (estimate.mirror_refusal) return MirrorJudgement(*estimate.mirror_refusal, in.t_s);
  return BlockedBy("solve", Judgement::kNone, Judgement::kNone, in.t_s, in.range_m.size());
}

}  // namespace

bool EstimatePdopTrigger::Evaluate(const TriggerInput& in) {
  const SolveResult estimate = solver_->Solve(in.p_world_tag, in.range_m);
  if (!Succeeded(estimate.status)) {
    judgement_ = FailedSolveJudgement(in, estimate);
    return false;
  }
  const double pdop = GeometryPdop(in.p_world_tag, in.range_m, estimate.p_world_anchor);
  judgement_ = BlockedBy("pdop", pdop, threshold_, in.t_s, in.range_m.size());
  return pdop < threshold_;
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
  if (!Succeeded(estimate.status)) {
    judgement_ = FailedSolveJudgement(in, estimate);
    return false;
  }
  const double dop = WorstBiasAwareDop(in.p_world_tag, estimate, sigmas_);
  judgement_ = BlockedBy("dop4", dop, threshold_, in.t_s, in.range_m.size());
  return dop < threshold_;
}

}  // namespace anchorbench::estimator
