#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/robust_kernel.hpp"
#include "anchorbench/estimator/solver_registry.hpp"

namespace anchorbench::estimator {

// Any NLopt algorithm as the parameter step of the adaptive kernel's alternation (Eq. (12)):
// theta = (p_A, gamma) first at alpha = 2, then alpha chosen from the residuals exactly as in
// lm_adaptive and theta minimized at that alpha by the NLopt algorithm, until both settle. (Tried
// first: NLopt on (p_A, gamma, alpha) jointly. Derivative-free algorithms then fell onto the
// alpha = alpha_min plateau metres from the anchor in 3 of 5 outlier trials; docs/method.md.)
// Search box: the LS seed +- 20 m (p_A) and +- 5 m (gamma); a minimum on its edge is reported as
// kNoConvergence. Gradient-based algorithms get central differences; stochastic ones are seeded
// per solve (NLopt's generator is per thread), so results repeat.
class NloptSolver : public Solver {
 public:
  // nullptr-free construction: use Create, which rejects unknown algorithm names.
  static std::unique_ptr<NloptSolver> Create(const std::string& algorithm, const AnchorSolverOptions& options,
                                             std::uint64_t seed);

  SolveResult Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const override;

 private:
  NloptSolver(int algorithm, const AnchorSolverOptions& options, std::uint64_t seed);

  int algorithm_;  // nlopt_algorithm
  AnchorSolverOptions options_;
  std::uint64_t seed_;
  std::shared_ptr<const LogPartitionTable> table_;
};

}  // namespace anchorbench::estimator
