#include "anchorbench/estimator/triggers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "anchorbench/estimator/pdop.hpp"

namespace anchorbench::estimator {

Judgement SolvedJudgement(const TriggerInput& in, const SolveResult& estimate, std::string_view test, double value,
                          double threshold) {
  if (estimate.mirror_refusal) return MirrorJudgement(*estimate.mirror_refusal, in.t_s);
  Judgement j;
  j.t_s = in.t_s;
  j.samples = in.range_m.size();
  j.blocked_by = Succeeded(estimate.status) ? test : std::string_view("solve");
  if (Succeeded(estimate.status)) {
    j.value = value;
    j.limit = threshold;
  }
  return j;
}

bool EstimatePdopTrigger::Evaluate(const TriggerInput& in) {
  const SolveResult estimate = solver_->Solve(in.p_world_tag, in.range_m);
  const double pdop = Succeeded(estimate.status) ? GeometryPdop(in.p_world_tag, in.range_m, estimate.p_world_anchor)
                                                 : std::numeric_limits<double>::infinity();
  judgement_ = SolvedJudgement(in, estimate, "pdop", pdop, threshold_);
  return Succeeded(estimate.status) && pdop < threshold_;
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
  const double dop = Succeeded(estimate.status) ? WorstBiasAwareDop(in.p_world_tag, estimate, sigmas_)
                                                : std::numeric_limits<double>::infinity();
  judgement_ = SolvedJudgement(in, estimate, "dop4", dop, threshold_);
  return Succeeded(estimate.status) && dop < threshold_;
}

}  // namespace anchorbench::estimator
