#include "anchorbench/estimator/nlopt_solver.hpp"

#include <array>
#include <cmath>
#include <vector>

#include <nlopt.hpp>

#include "anchorbench/estimator/ls_solver.hpp"
#include "anchorbench/estimator/nls_solver.hpp"
#include "residual_arrays.hpp"

namespace anchorbench::estimator {
namespace {

// Our settings, not the paper's (it uses LM). The box keeps global algorithms near the LS seed;
// the first steps start local derivative-free algorithms at the scale of a range error instead
// of a fraction of the box; the tolerances ask for convergence far below the 1 mm step tolerance
// of the alternation, within a budget no well-posed problem here comes near.
constexpr double kBoxHalfWidthPosition_m = 20.0;
constexpr double kBoxHalfWidthBias_m = 5.0;
constexpr std::array<double, 4> kFirstStep = {0.5, 0.5, 0.5, 0.2};  // p_A (m), gamma (m)
constexpr double kRelativeXTolerance = 1e-10;
constexpr double kRelativeFTolerance = 1e-14;
constexpr int kMaxEvaluations = 20000;
constexpr int kMaxAlternations = 30;
constexpr double kRelativeStepForGradient = 1e-6;  // central differences for gradient-based algorithms

using Theta = std::vector<double>;  // (x, y, z, gamma), as NLopt takes it

// The robust cost of Eq. (12) at a fixed kernel shape alpha, over theta = x[0..3], evaluated on
// all residuals at once (the arrays are reused from call to call).
struct Problem {
  const internal::SampleArrays& samples;
  double c;
  double alpha;

  double Objective(const double* x) const {
    return internal::Pass(samples, Eigen::Vector4d(x[0], x[1], x[2], x[3]), c, {alpha, true, false, nullptr}).cost;
  }
};

double Evaluate(unsigned n, const double* x, double* gradient, void* data) {
  const Problem& problem = *static_cast<const Problem*>(data);
  if (gradient) {
    std::vector<double> shifted(x, x + n);
    for (unsigned i = 0; i < n; ++i) {
      const double h = kRelativeStepForGradient * std::max(1.0, std::abs(x[i]));
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

// The alpha step: the shape that best explains the residuals at theta (as lm_adaptive).
double SelectAlpha(AlphaSelector& selector, const Problem& problem, const Theta& x, std::optional<double> previous) {
  internal::Pass(problem.samples, Eigen::Vector4d(x[0], x[1], x[2], x[3]), problem.c, {2.0, false, false, &selector});
  return selector.Select(previous);
}

// The theta step: the NLopt algorithm on the cost at a fixed alpha, inside the box, from x.
void MinimizeTheta(int algorithm, Problem& problem, const Theta& lower, const Theta& upper, Theta& x) {
  // NLopt takes a non-const pointer to the problem; the objective only reads it.
  try {
    nlopt::opt optimizer(static_cast<nlopt::algorithm>(algorithm), 4);
    nlopt::opt local(nlopt::LN_BOBYQA, 4);  // for the algorithms that need a local one (MLSL, AUGLAG)
    local.set_xtol_rel(kRelativeXTolerance);
    optimizer.set_local_optimizer(local);
    optimizer.set_lower_bounds(lower);
    optimizer.set_upper_bounds(upper);
    optimizer.set_min_objective(Evaluate, &problem);
    optimizer.set_initial_step(std::vector<double>(kFirstStep.begin(), kFirstStep.end()));
    optimizer.set_xtol_rel(kRelativeXTolerance);
    optimizer.set_ftol_rel(kRelativeFTolerance);
    optimizer.set_maxeval(kMaxEvaluations);
    double cost = 0.0;
    optimizer.optimize(x, cost);
  } catch (const std::exception&) {
    // NLopt gave up (round-off, invalid arguments, ...); x holds its best point so far.
  }
}

double Distance(const Theta& a, const Theta& b) {
  return std::sqrt(std::pow(a[0] - b[0], 2) + std::pow(a[1] - b[1], 2) + std::pow(a[2] - b[2], 2) +
                   std::pow(a[3] - b[3], 2));
}

}  // namespace

bool NloptSolver::IsStochastic(int algorithm) {
  switch (static_cast<nlopt_algorithm>(algorithm)) {
    case NLOPT_GN_DIRECT_L_RAND:
    case NLOPT_GN_DIRECT_L_RAND_NOSCAL:
    case NLOPT_GD_STOGO_RAND:
    case NLOPT_LN_PRAXIS:
    case NLOPT_GN_CRS2_LM:
    case NLOPT_GN_MLSL:
    case NLOPT_GD_MLSL:
    case NLOPT_G_MLSL:
    case NLOPT_GN_ISRES:
    case NLOPT_GN_ESCH:
      return true;
    default:
      return false;
  }
}

// NLopt's own nlopt_algorithm_from_string returns -1 as an nlopt_algorithm, a value outside the
// enumeration: undefined behaviour to even load.
int NloptSolver::AlgorithmNumber(const std::string& name) {
  for (int a = 0; a < NLOPT_NUM_ALGORITHMS; ++a) {
    const char* known = nlopt_algorithm_to_string(static_cast<nlopt_algorithm>(a));
    if (known && name == known) return a;
  }
  return -1;
}

bool NloptSolver::Accepts(const std::string& algorithm, std::string* why) {
  const int a = AlgorithmNumber(algorithm);
  if (a < 0) {
    if (why) *why = "'" + algorithm + "' is not an NLopt algorithm (e.g. LN_BOBYQA, LN_SBPLX, LD_LBFGS)";
    return false;
  }
  if (IsStochastic(a)) {
    if (why) {
      *why = "'" + algorithm + "' draws from NLopt's process-wide random generator, so its results would not repeat; "
             "choose a deterministic algorithm";
    }
    return false;
  }
  return true;
}

std::unique_ptr<NloptSolver> NloptSolver::Create(const std::string& algorithm, const AnchorSolverOptions& options,
                                                 std::shared_ptr<const LogPartitionTable> table, std::string* why) {
  if (!Accepts(algorithm, why)) return nullptr;
  if (options.height_prior) {  // its cost is the ranges' alone
    if (why) *why = "nlopt:" + algorithm + " takes no height prior (the LS and lm_* solvers do)";
    return nullptr;
  }
  const int a = AlgorithmNumber(algorithm);
  if (!table || table->truncation() != options.nls.truncation || table->alpha_min() != options.nls.alpha_min) {
    table = std::make_shared<const LogPartitionTable>(options.nls.truncation, options.nls.alpha_min);
  }
  return std::unique_ptr<NloptSolver>(new NloptSolver(a, options, std::move(table)));
}

NloptSolver::NloptSolver(int algorithm, const AnchorSolverOptions& options, std::shared_ptr<const LogPartitionTable> table)
    : algorithm_(algorithm), options_(options), table_(std::move(table)) {}

SolveResult NloptSolver::Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const {
  const SolveResult seed = SolveDoubleDifferenceLs(p_world_tag, range_m, options_.ls);
  if (!Succeeded(seed.status)) return seed;
  Theta x = {seed.p_world_anchor.x(), seed.p_world_anchor.y(), seed.p_world_anchor.z(), seed.bias_m};
  const Theta half = {kBoxHalfWidthPosition_m, kBoxHalfWidthPosition_m, kBoxHalfWidthPosition_m, kBoxHalfWidthBias_m};
  Theta lower(4), upper(4);
  for (int i = 0; i < 4; ++i) {
    lower[i] = x[i] - half[i];
    upper[i] = x[i] + half[i];
  }
  const internal::SampleArrays samples(p_world_tag, range_m);
  Problem problem{samples, options_.nls.kernel_scale_m, 2.0};
  AlphaSelector selector(table_);
  SolveStatus status = SolveStatus::kMaxIterations;
  int alternation = 0;
  // First theta at alpha = 2 (into the basin), then alpha from the residuals and theta at that
  // alpha, until both settle.
  for (; alternation < kMaxAlternations; ++alternation) {
    const double previous_alpha = problem.alpha;
    if (alternation > 0) {
      problem.alpha = SelectAlpha(selector, problem, x, alternation > 1 ? std::optional(problem.alpha) : std::nullopt);
    }
    const Theta before = x;
    MinimizeTheta(algorithm_, problem, lower, upper, x);
    if (alternation > 0 && Distance(x, before) < options_.nls.step_tolerance_m &&
        std::abs(problem.alpha - previous_alpha) < options_.nls.alpha_tolerance) {
      status = SolveStatus::kConverged;
      break;
    }
  }
  // A minimum on the edge of the search box is the box's, not the data's: with alpha at alpha_min
  // and every residual large the objective is nearly flat far from the anchor.
  for (int i = 0; i < 4; ++i) {
    if (x[i] <= lower[i] + 1e-9 || x[i] >= upper[i] - 1e-9) status = SolveStatus::kNoConvergence;
  }
  return SummarizeSolution(p_world_tag, range_m, Eigen::Vector4d(x[0], x[1], x[2], x[3]), problem.alpha,
                           problem.c, status, alternation + 1);
}

}  // namespace anchorbench::estimator
