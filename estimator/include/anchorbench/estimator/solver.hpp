#pragma once

#include <span>

#include <Eigen/Core>

#include "anchorbench/estimator/solve_result.hpp"

namespace anchorbench::estimator {

// A solver for (p_A, gamma) from tag positions and ranges. Implementations report failure through
// SolveResult::status (never an exception, never a non-finite estimate with a success status).
class Solver {
 public:
  virtual ~Solver() = default;
  virtual SolveResult Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const = 0;
};

}  // namespace anchorbench::estimator
