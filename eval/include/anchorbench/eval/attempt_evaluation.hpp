#pragma once

#include <optional>
#include <span>

#include <Eigen/Core>

#include "anchorbench/estimator/solve_result.hpp"
#include "anchorbench/schema/attempt.hpp"

namespace anchorbench::eval {

// e^T P^-1 e, or nothing if P is not positive definite.
std::optional<double> Nees(const Eigen::VectorXd& error, const Eigen::MatrixXd& covariance);

// `estimate` is the initialized solve (nullptr if the attempt did not initialize).
schema::AttemptEvaluation Evaluate(std::span<const Eigen::Vector3d> p_world_tag_used, const estimator::SolveResult* estimate,
                           const schema::AnchorTruth& truth);

}  // namespace anchorbench::eval
