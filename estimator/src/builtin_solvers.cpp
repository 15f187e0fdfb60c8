#include <functional>

#include "anchorbench/estimator/ls_solver.hpp"
#include "anchorbench/estimator/nlopt_solver.hpp"
#include "anchorbench/estimator/solver_registry.hpp"

namespace anchorbench::estimator {
namespace {

// A solver that is one function of the data (the closed-form LS solutions).
class FunctionSolver : public Solver {
 public:
  using Function = std::function<SolveResult(std::span<const Eigen::Vector3d>, std::span<const double>)>;
  explicit FunctionSolver(Function function) : function_(std::move(function)) {}
  SolveResult Solve(std::span<const Eigen::Vector3d> p, std::span<const double> d) const override {
    return function_(p, d);
  }

 private:
  Function function_;
};

// LS + LM with the configured options and the given kernel.
SolverRegistry::Factory LmWith(KernelMode kernel, double fixed_alpha = 1.0) {
  return [kernel, fixed_alpha](const std::string&, const SolverContext& context) {
    AnchorSolverOptions chosen = context.options;
    chosen.nls.kernel = kernel;
    chosen.nls.fixed_alpha = fixed_alpha;
    return std::unique_ptr<Solver>(new AnchorSolver(chosen));
  };
}

}  // namespace

void RegisterBuiltinSolvers(SolverRegistry& registry) {
  registry.Register("ls_single", "single-difference LS with bias (the authors' earlier library, 'SINGLE')",
                    [](const std::string&, const SolverContext&) {
                      return std::unique_ptr<Solver>(new FunctionSolver(
                          [](auto p, auto d) { return SolveSingleDifferenceLs(p, d); }));
                    });
  registry.Register("ls_double", "double-difference LS, Eqs. (9)-(10), pivot as configured (ls.pivot)",
                    [](const std::string&, const SolverContext& context) {
                      return std::unique_ptr<Solver>(new DoubleDifferenceLsSolver(context.options.ls));
                    });
  registry.Register("lm_l2", "LS + Levenberg-Marquardt on plain least squares, Eq. (11)", LmWith(KernelMode::kL2));
  registry.Register("lm_huber", "LS + LM with a smooth Huber kernel (Barron alpha = 1, pseudo-Huber)",
                    LmWith(KernelMode::kFixed, 1.0));
  registry.Register("lm_cauchy", "LS + LM with the Cauchy kernel (alpha = 0)", LmWith(KernelMode::kFixed, 0.0));
  registry.Register("lm_adaptive", "LS + LM with the adaptive robust kernel, Eqs. (12)-(13): the paper's solver",
                    LmWith(KernelMode::kAdaptive));
  registry.RegisterPrefix("nlopt:", "any NLopt algorithm (e.g. nlopt:LN_BOBYQA) as the parameter step of the adaptive kernel",
                          [](const std::string& name, const SolverContext& context) {
                            return std::unique_ptr<Solver>(NloptSolver::Create(
                                name.substr(std::string("nlopt:").size()), context.options, context.seed));
                          });
}

}  // namespace anchorbench::estimator
