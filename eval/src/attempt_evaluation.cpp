#include "anchorbench/eval/attempt_evaluation.hpp"

#include <cmath>

#include <Eigen/Cholesky>

#include "anchorbench/eval/true_geometry.hpp"

namespace anchorbench::eval {

std::optional<double> Nees(const Eigen::VectorXd& error, const Eigen::MatrixXd& covariance) {
  if (!covariance.allFinite()) return std::nullopt;
  const Eigen::LLT<Eigen::MatrixXd> cholesky(covariance);
  if (cholesky.info() != Eigen::Success) return std::nullopt;  // not positive definite
  const double nees = error.dot(cholesky.solve(error));
  return std::isfinite(nees) ? std::optional(nees) : std::nullopt;
}

schema::AttemptEvaluation Evaluate(std::span<const Eigen::Vector3d> p_world_tag_used, const estimator::SolveResult* estimate,
                           const schema::AnchorTruth& truth) {
  schema::AttemptEvaluation evaluation;
  TrueGeometry geometry(truth.p_world_anchor);
  for (const Eigen::Vector3d& p : p_world_tag_used) geometry.Add(p);
  evaluation.pdop_true = geometry.Pdop();
  const double bias_aware = geometry.BiasAwareDop();
  if (std::isfinite(bias_aware)) {
    evaluation.bias_aware_dop = bias_aware;
    evaluation.bias_aware_hdop = geometry.BiasAwareHorizontalDop();
    evaluation.bias_aware_vdop = geometry.BiasAwareVerticalDop();
  }
  if (estimate) {
    evaluation.error_xyz_m = estimate->p_world_anchor - truth.p_world_anchor;
    evaluation.error_m = (estimate->p_world_anchor - truth.p_world_anchor).norm();
    evaluation.nees_position = Nees(*evaluation.error_xyz_m, estimate->covariance.topLeftCorner<3, 3>());
    if (truth.bias_m) {
      evaluation.bias_error_m = estimate->bias_m - *truth.bias_m;
      Eigen::Vector4d error;
      error << *evaluation.error_xyz_m, *evaluation.bias_error_m;
      evaluation.nees = Nees(error, estimate->covariance);
    }
  }
  return evaluation;
}

}  // namespace anchorbench::eval
