#include "anchorbench/estimator/nlopt_solver.hpp"

#include <cmath>
#include <vector>

#include <nlopt.hpp>

#include "anchorbench/estimator/ls_solver.hpp"
#include "anchorbench/estimator/nls_solver.hpp"

namespace anchorbench::estimator {
namespace {

constexpr int kMaxEvaluations = 20000;

constexpr int kMaxAlternations = 30;

// The robust cost of Eq. (12) at a fixed kernel shape alpha, over theta = x[0..3].
struct Problem {
  std::span<const Eigen::Vector3d> p;
  std::span<const double> d;
  double c;
  double alpha;

  double Objective(const double* x) const {
    const Eigen::Vector3d anchor(x[0], x[1], x[2]);
    double sum_rho = 0.0;
    for (std::size_t k = 0; k < d.size(); ++k) sum_rho += Rho(((p[k] - anchor).norm() + x[3] - d[k]) / c, alpha);
    return sum_rho;
  }
};

double Evaluate(unsigned n, const double* x, double* gradient, void* data) {
  const Problem& problem = *static_cast<const Problem*>(data);
  if (gradient) {  // central differences for the gradient-based algorithms
    std::vector<double> shifted(x, x + n);
    for (unsigned i = 0; i < n; ++i) {
      const double h = 1e-6 * std::max(1.0, std::abs(x[i]));
      shifted[i] = x[i] + h;
      const double up = problem.Objective(shifted.data());
      shifted[i] = x[i] - h;
      const double down = problem.Objective(shifted.data());
      shifted[i] = x[i];
      gradient[i] = (up - down) / (2.0 * h);
    }
  }
  return problem.Objective(x);
}

}  // namespace

std::unique_ptr<NloptSolver> NloptSolver::Create(const std::string& algorithm, const AnchorSolverOptions& options,
                                                 std::uint64_t seed) {
  const nlopt_algorithm a = nlopt_algorithm_from_string(algorithm.c_str());
  if (static_cast<int>(a) < 0 || a >= NLOPT_NUM_ALGORITHMS) return nullptr;
  return std::unique_ptr<NloptSolver>(new NloptSolver(static_cast<int>(a), options, seed));
}

NloptSolver::NloptSolver(int algorithm, const AnchorSolverOptions& options, std::uint64_t seed)
    : algorithm_(algorithm), options_(options), seed_(seed),
      table_(LogPartitionTable::Shared(options.nls.truncation, options.nls.alpha_min)) {}

SolveResult NloptSolver::Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const {
  const SolveResult seed_solution = SolveDoubleDifferenceLs(p_world_tag, range_m, options_.ls);
  if (!Succeeded(seed_solution.status)) return seed_solution;
  std::vector<double> x = {seed_solution.p_world_anchor.x(), seed_solution.p_world_anchor.y(),
                           seed_solution.p_world_anchor.z(), seed_solution.bias_m};
  const std::vector<double> lower = {x[0] - 20.0, x[1] - 20.0, x[2] - 20.0, x[3] - 5.0};
  const std::vector<double> upper = {x[0] + 20.0, x[1] + 20.0, x[2] + 20.0, x[3] + 5.0};
  const double c = options_.nls.kernel_scale_m;
  SolveStatus status = SolveStatus::kMaxIterations;
  AlphaSelector selector(table_);
  double alpha = 2.0;
  int alternation = 0;
  // The alternation of lm_adaptive with NLopt as the theta step: first theta at alpha = 2 (into
  // the basin), then alpha from the residuals and theta at that alpha, until both settle.
  for (; alternation < kMaxAlternations; ++alternation) {
    const double previous_alpha = alpha;
    if (alternation > 0) {
      selector.Clear();
      const Eigen::Vector3d anchor(x[0], x[1], x[2]);
      for (std::size_t k = 0; k < range_m.size(); ++k) {
        selector.Add(((p_world_tag[k] - anchor).norm() + x[3] - range_m[k]) / c);
      }
      alpha = selector.Select(alternation > 1 ? std::optional<double>(alpha) : std::nullopt);
    }
    const Problem problem{p_world_tag, range_m, c, alpha};
    const std::vector<double> before = x;
    try {
      nlopt::opt optimizer(static_cast<nlopt::algorithm>(algorithm_), 4);
      nlopt::opt local(nlopt::LN_BOBYQA, 4);  // for the algorithms that need a local one (MLSL, AUGLAG)
      local.set_xtol_rel(1e-10);
      optimizer.set_local_optimizer(local);
      optimizer.set_lower_bounds(lower);
      optimizer.set_upper_bounds(upper);
      optimizer.set_min_objective(Evaluate, const_cast<Problem*>(&problem));
      // Local derivative-free algorithms start from a simplex/trust region of this size; the
      // default (a fraction of the +-20 m box) starts far from the anchor.
      optimizer.set_initial_step(std::vector<double>{0.5, 0.5, 0.5, 0.2});
      optimizer.set_xtol_rel(1e-10);
      optimizer.set_ftol_rel(1e-14);
      optimizer.set_maxeval(kMaxEvaluations);
      nlopt::srand(static_cast<unsigned long>(seed_ + static_cast<std::uint64_t>(alternation)));
      double cost = 0.0;
      optimizer.optimize(x, cost);
    } catch (const std::exception&) {
      // NLopt gave up (round-off, invalid arguments, ...); x holds its best point so far.
    }
    const double step_m = std::sqrt(std::pow(x[0] - before[0], 2) + std::pow(x[1] - before[1], 2) +
                                    std::pow(x[2] - before[2], 2) + std::pow(x[3] - before[3], 2));
    if (alternation > 0 && step_m < options_.nls.step_tolerance_m &&
        std::abs(alpha - previous_alpha) < options_.nls.alpha_tolerance) {
      status = SolveStatus::kConverged;
      break;
    }
  }
  // A minimum on the edge of the search box is the box's, not the data's: with alpha at alpha_min
  // and every residual large the objective is nearly flat far from the anchor.
  for (int i = 0; i < 4; ++i) {
    if (x[i] <= lower[i] + 1e-9 || x[i] >= upper[i] - 1e-9) status = SolveStatus::kNoConvergence;
  }
  Eigen::Vector4d theta(x[0], x[1], x[2], x[3]);
  return SummarizeSolution(p_world_tag, range_m, theta, alpha, c, status, alternation + 1);
}

}  // namespace anchorbench::estimator
