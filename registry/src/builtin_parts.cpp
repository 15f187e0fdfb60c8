// The built-in solvers, filters and triggers of the estimator, by name.
#include <functional>
#include <stdexcept>

#include "anchorbench/estimator/certified_trigger.hpp"
#include "anchorbench/estimator/consistency_filter.hpp"
#include "anchorbench/estimator/ls_solver.hpp"
#include "anchorbench/estimator/nlopt_solver.hpp"
#include "anchorbench/estimator/ransac_solver.hpp"
#include "anchorbench/estimator/triggers.hpp"
#include "anchorbench/registry/components.hpp"

namespace anchorbench::registry {
namespace {

using estimator::KernelMode;
using estimator::Solver;

// A solver that is one function of the data (the closed-form LS solutions).
class FunctionSolver : public Solver {
 public:
  using Function = std::function<estimator::SolveResult(std::span<const Eigen::Vector3d>, std::span<const double>)>;
  explicit FunctionSolver(Function function) : function_(std::move(function)) {}
  estimator::SolveResult Solve(std::span<const Eigen::Vector3d> p, std::span<const double> d) const override {
    return function_(p, d);
  }

 private:
  Function function_;
};

// The shared log-partition table the adaptive kernel needs, if the context offers the tables.
std::shared_ptr<const estimator::LogPartitionTable> TableFor(const SolverContext& context) {
  const estimator::NlsOptions& nls = context.options.nls;
  return context.tables ? context.tables->Get(nls.truncation, nls.alpha_min) : nullptr;
}

// LS + LM with the configured options and the given kernel.
SolverRegistry::Factory LmWith(KernelMode kernel, double fixed_alpha = 1.0) {
  return [kernel, fixed_alpha](const std::string&, const SolverContext& context) {
    estimator::AnchorSolverOptions chosen = context.options;
    chosen.nls.kernel = kernel;
    chosen.nls.fixed_alpha = fixed_alpha;
    return std::unique_ptr<Solver>(new estimator::AnchorSolver(
        chosen, kernel == KernelMode::kAdaptive ? TableFor(context) : nullptr));
  };
}

constexpr const char* kNloptPrefix = "nlopt:";

estimator::SolveCadence Cadence(const schema::TriggerConfig& options) {
  return {options.evaluate_every, options.evaluate_growth};
}

}  // namespace

void RegisterBuiltinSolvers(SolverRegistry& registry) {
  registry.Register("ls_single", "single-difference LS with bias (the authors' earlier library, 'SINGLE')",
                    [](const std::string&, const SolverContext& context) {
                      if (context.options.height_prior) {
                        throw std::invalid_argument("ls_single takes no height prior (ls_double and lm_* do)");
                      }
                      return std::unique_ptr<Solver>(new FunctionSolver(
                          [](auto p, auto d) { return estimator::SolveSingleDifferenceLs(p, d); }));
                    });
  registry.Register("ls_double", "double-difference LS, Eqs. (9)-(10), pivot as configured (ls.pivot)",
                    [](const std::string&, const SolverContext& context) {
                      return std::unique_ptr<Solver>(new estimator::DoubleDifferenceLsSolver(context.options.ls, context.options.height_prior));
                    });
  registry.Register("lm_l2", "LS + Levenberg-Marquardt on plain least squares, Eq. (11)", LmWith(KernelMode::kL2));
  registry.Register("lm_huber", "LS + LM with a smooth Huber kernel (Barron alpha = 1, pseudo-Huber)",
                    LmWith(KernelMode::kFixed, 1.0));
  registry.Register("lm_cauchy", "LS + LM with the Cauchy kernel (alpha = 0)", LmWith(KernelMode::kFixed, 0.0));
  registry.Register("lm_adaptive", "LS + LM with the adaptive robust kernel, Eqs. (12)-(13): the paper's solver",
                    LmWith(KernelMode::kAdaptive));
  registry.RegisterPrefix(
      kNloptPrefix, "any deterministic NLopt algorithm (e.g. nlopt:LN_BOBYQA) as the parameter step of the adaptive kernel",
      [](const std::string& name, const SolverContext& context) {
        std::string why;
        auto solver = estimator::NloptSolver::Create(name.substr(std::string(kNloptPrefix).size()), context.options,
                                                     TableFor(context), &why);
        if (!solver) throw std::invalid_argument(why);
        return std::unique_ptr<Solver>(std::move(solver));
      },
      [](const std::string& algorithm, std::string* why) { return estimator::NloptSolver::Accepts(algorithm, why); });
}

void RegisterBuiltinFilters(FilterRegistry& registry) {
  registry.Register("none", "every range accepted (the do-nothing baseline)",
                    [](const std::string&, const FilterContext&) { return std::make_unique<estimator::NullFilter>(); });
  registry.Register("consistency", "the triangle-inequality check of Sec. III-B, online (filter.tau_m)",
                    [](const std::string&, const FilterContext& context) {
                      return std::make_unique<estimator::ConsistencyFilter>(context.options.consistency);
                    });
  registry.Register("ransac", "RANSAC around the solver at solve time (Jung et al. 2024; Table II; filter.ransac)",
                    [](const std::string&, const FilterContext& context) {
                      return std::make_unique<estimator::RansacFilter>(context.options.ransac, context.seed);
                    });
}

void RegisterBuiltinTriggers(TriggerRegistry& registry) {
  using Context = TriggerContext;
  registry.Register("pdop_closest_point",
                    "closest-point PDOP < trigger.pdop_threshold, Eq. (4), O(1): the paper's trigger",
                    [](const std::string&, const Context& c) {
                      return std::make_unique<estimator::ClosestPointPdopTrigger>(c.options.pdop_threshold);
                    });
  registry.Register("pdop_ls", "PDOP at the LS estimate < trigger.pdop_threshold (on trigger.evaluate_every / evaluate_growth)",
                    [](const std::string&, const Context& c) {
                      return std::make_unique<estimator::EstimatePdopTrigger>(
                          std::make_shared<estimator::DoubleDifferenceLsSolver>(c.solver_options.ls, c.solver_options.height_prior),
                          c.options.pdop_threshold, Cadence(c.options));
                    });
  registry.Register("pdop_nls",
                    "PDOP at the solver's estimate < trigger.pdop_threshold (on trigger.evaluate_every / evaluate_growth)",
                    [](const std::string&, const Context& c) {
                      if (!c.solver) throw std::invalid_argument("needs the anchor's solver");
                      return std::make_unique<estimator::EstimatePdopTrigger>(c.solver, c.options.pdop_threshold,
                                                                              Cadence(c.options));
                    });
  registry.Register("dop4_closest_point",
                    "closest-point DOP with a bias column < trigger.bias_aware_threshold, O(1) (ours)",
                    [](const std::string&, const Context& c) {
                      return std::make_unique<estimator::ClosestPointDopTrigger>(
                          &estimator::ClosestPointPdop::BiasAwareValue, c.options.bias_aware_threshold, "dop4");
                    });
  registry.Register("hdop_closest_point",
                    "closest-point DOP of x-y alone < trigger.horizontal_threshold, O(1): for a height prior on a "
                    "flat path (ours)",
                    [](const std::string&, const Context& c) {
                      return std::make_unique<estimator::ClosestPointDopTrigger>(
                          &estimator::ClosestPointPdop::HorizontalValue, c.options.horizontal_threshold, "hdop");
                    });
  registry.Register("dop4_confidence",
                    "worst bias-aware DOP over the trigger.confidence_sigmas region of the solver's estimate < "
                    "trigger.confidence_threshold (on trigger.evaluate_every / evaluate_growth; ours)",
                    [](const std::string&, const Context& c) {
                      if (!c.solver) throw std::invalid_argument("needs the anchor's solver");
                      return std::make_unique<estimator::ConfidenceRegionDopTrigger>(
                          c.solver, c.options.confidence_threshold, Cadence(c.options), c.options.confidence_sigmas);
                    });
  registry.Register("certified",
                    "fires once the data rule out every anchor position farther than certificate.accuracy_m from the "
                    "estimate, its mirror included (on trigger.evaluate_every / evaluate_growth; ours)",
                    [](const std::string&, const Context& c) {
                      if (!c.solver) throw std::invalid_argument("needs the anchor's solver");
                      return std::make_unique<estimator::CertifiedTrigger>(
                          c.solver, c.solver_options, c.certificate, c.initializer.height_check,
                          c.initializer.tag_biases, c.travel_bias,
                          estimator::SolveCadence(c.options.evaluate_every, c.certificate.evaluate_growth));
                    });
  registry.Register("fixed_window", "the baseline: one solve on all of an anchor's data at the end of the run",
                    [](const std::string&, const Context&) { return std::make_unique<estimator::FixedWindowTrigger>(); });
  registry.Register("sample_count", "after trigger.sample_count accepted samples",
                    [](const std::string&, const Context& c) {
                      return std::make_unique<estimator::SampleCountTrigger>(c.options.sample_count);
                    });
  registry.Register("timeout", "trigger.timeout_s after the anchor's first accepted sample",
                    [](const std::string&, const Context& c) {
                      return std::make_unique<estimator::TimeoutTrigger>(c.options.timeout_s);
                    });
}

}  // namespace anchorbench::registry
