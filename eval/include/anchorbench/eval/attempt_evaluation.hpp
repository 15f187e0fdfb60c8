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
  std::optional<double> bias_aware_dop;  // finite only; sigma_d times it is the CRLB on the position error
  // Initialized attempts only:
  std::optional<Eigen::Vector3d> error_xyz_m;  // estimate - truth
  std::optional<double> error_m;               // its norm
  std::optional<double> bias_error_m;          // estimated - true bias, where the true bias is known
};

// `estimate` is the initialized solve (nullptr if the attempt did not initialize).
AttemptEvaluation Evaluate(std::span<const Eigen::Vector3d> p_world_tag_used, const estimator::SolveResult* estimate,
                           const AnchorTruth& truth);

}  // namespace anchorbench::eval
