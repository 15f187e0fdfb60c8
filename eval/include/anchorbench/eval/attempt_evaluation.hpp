#pragma once

#include <optional>
#include <span>

#include <Eigen/Core>

#include "anchorbench/estimator/solve_result.hpp"

namespace anchorbench::eval {

// What is known of an anchor in simulation, or from a survey (anchors.csv).
struct AnchorTruth {
  Eigen::Vector3d p_world_anchor = Eigen::Vector3d::Zero();
  std::optional<double> bias_m;
};

// One attempt measured against the truth.
struct AttemptEvaluation {
  // On the attempt's data (the samples of its solve, or all buffered if none initialized it):
  double pdop_true = 0.0;                // Eqs. (2)-(3) at the true anchor (+inf if undefined)
  std::optional<double> bias_aware_hdop;  // its horizontal and vertical parts (TrueGeometry), finite only
  std::optional<double> bias_aware_vdop;
  std::optional<double> bias_aware_dop;  // finite only; sigma_d times it is the CRLB on the position error
  // Initialized attempts only:
  std::optional<Eigen::Vector3d> error_xyz_m;  // estimate - truth
  std::optional<double> error_m;               // its norm
  std::optional<double> bias_error_m;          // estimated - true bias, where the true bias is known
  // Normalized estimation error squared, e^T P^-1 e, of the solve's own covariance P: of the
  // position (3 dof), and of (p_A, gamma) where the true bias is known (4 dof). A credible
  // covariance gives a chi-square variable of that many degrees of freedom. Absent where P is
  // not positive definite (e.g. a solver that reports none).
  std::optional<double> nees_position;
  std::optional<double> nees;
};

// e^T P^-1 e, or nothing if P is not positive definite.
std::optional<double> Nees(const Eigen::VectorXd& error, const Eigen::MatrixXd& covariance);

// `estimate` is the initialized solve (nullptr if the attempt did not initialize).
AttemptEvaluation Evaluate(std::span<const Eigen::Vector3d> p_world_tag_used, const estimator::SolveResult* estimate,
                           const AnchorTruth& truth);

}  // namespace anchorbench::eval
