#pragma once

#include <cstdint>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/registry.hpp"
#include "anchorbench/estimator/solver.hpp"

namespace anchorbench::estimator {

// What a solver factory gets: the configured LS/NLS options (kernel scale, tolerances, ...) and a
// seed for solvers that draw random numbers (one per anchor attempt, so results repeat).
struct SolverContext {
  AnchorSolverOptions options;
  std::uint64_t seed = 0;
};

using SolverRegistry = Registry<Solver, SolverContext>;

// ls_single, ls_double, lm_l2, lm_huber, lm_cauchy, lm_adaptive, nlopt:<ALGORITHM>.
void RegisterBuiltinSolvers(SolverRegistry& registry);

}  // namespace anchorbench::estimator
