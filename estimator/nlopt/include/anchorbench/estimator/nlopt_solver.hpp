#pragma once

#include <memory>
#include <span>
#include <string>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/robust_kernel.hpp"

namespace anchorbench::estimator {

// Any deterministic NLopt algorithm as the parameter step of the adaptive kernel's alternation
// (Eq. (12)): theta = (p_A, gamma) first at alpha = 2, then alpha chosen from the residuals exactly
// as in lm_adaptive and theta minimized at that alpha by the NLopt algorithm, until both settle.
// (Tried first: NLopt on (p_A, gamma, alpha) jointly. Derivative-free algorithms then fell onto
// the alpha = alpha_min plateau metres from the anchor in 3 of 5 outlier trials; docs/method.md.)
// Search box: the LS seed +- 20 m (p_A) and +- 5 m (gamma); a minimum on its edge is reported as
// kNoConvergence. Gradient-based algorithms get central differences.
//
// Stochastic algorithms (CRS, ISRES, ESCH, MLSL with random points, PRAXIS, the randomized DIRECT
// and StoGO) are refused: they draw from NLopt's process-wide generator, so a result would depend
// on what ran before on the thread. A test checks this list against NLopt itself.
class NloptSolver : public Solver {
 public:
  // The solver, or nullptr with *why saying whether the algorithm is unknown or stochastic.
  static std::unique_ptr<NloptSolver> Create(const std::string& algorithm, const AnchorSolverOptions& options,
                                             std::shared_ptr<const LogPartitionTable> table, std::string* why);
  // Whether `algorithm` names a deterministic NLopt algorithm; *why says why not. Builds nothing.
  static bool Accepts(const std::string& algorithm, std::string* why);
  // Whether NLopt's algorithm (an nlopt_algorithm value) draws random numbers.
  static bool IsStochastic(int algorithm);
  // The nlopt_algorithm value of a name such as "LN_SBPLX", or -1.
  static int AlgorithmNumber(const std::string& algorithm);

  SolveResult Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const override;

 private:
  NloptSolver(int algorithm, const AnchorSolverOptions& options, std::shared_ptr<const LogPartitionTable> table);

  int algorithm_;  // nlopt_algorithm
  AnchorSolverOptions options_;
  std::shared_ptr<const LogPartitionTable> table_;
};

}  // namespace anchorbench::estimator
