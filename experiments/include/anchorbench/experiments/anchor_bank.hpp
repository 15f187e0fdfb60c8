#pragma once

#include <map>
#include <optional>
#include <string_view>
#include <vector>

#include "anchorbench/estimator/anchor_initializer.hpp"
#include "anchorbench/estimator/solver_registry.hpp"
#include "anchorbench/experiments/recorded_data.hpp"

namespace anchorbench::experiments {

std::string_view MethodName(estimator::InitStrategy strategy);  // "gated" | "fixed"

// The built-in solvers (ls_single, ..., nlopt:<ALGORITHM>), registered once.
const estimator::SolverRegistry& BuiltinSolvers();

// One anchor, one strategy: what happened, and how good it was when the truth is known.
struct AttemptOutcome {
  int anchor_id = 0;
  estimator::InitStrategy method = estimator::InitStrategy::kPdopGated;
  bool initialized = false;
  std::optional<double> t_init_s;   // when the solve ran (gated: trigger; fixed: end of data)
  int n_used = 0;                   // samples in the solve, or accepted so far if none ran
  double pdop_estimate = 0.0;       // closest-point PDOP at that moment (+inf if undefined)
  std::optional<double> pdop_true;  // Eq. (2)-(3) at the true anchor on the same samples
  std::optional<double> bias_aware_dop;  // sigma_d times this is the CRLB on the position error
  std::optional<estimator::SolveResult> solve;  // absent if the solver never ran
  std::optional<double> error_m;    // ||estimate - truth|| for initialized attempts with truth
};

// A gated and a fixed-window initializer for every anchor that shows up, fed from one time-ordered
// stream of samples (simulated or recorded).
class AnchorBank {
 public:
  // The solver named options.solver_name comes from `registry` (default: the built-ins).
  explicit AnchorBank(const estimator::InitializerOptions& options, const estimator::SolverRegistry* registry = nullptr);

  // Makes the anchor known before its first range, so it is reported even if none arrives.
  void AddAnchor(int anchor_id);

  // Feeds both strategies; returns the gated initializer's view (for traces).
  estimator::FeedResult Feed(const estimator::RangeSample& sample);

  // End of data at t_end_s: the fixed windows solve. One outcome per anchor and strategy, anchor
  // ids ascending, gated before fixed. `truth` (optional) adds pdop_true and error_m.
  std::vector<AttemptOutcome> Finish(double t_end_s, const std::map<int, AnchorTruth>* truth);

 private:
  struct Anchor {
    estimator::AnchorInitializer gated;
    estimator::AnchorInitializer fixed;
    std::optional<estimator::InitEvent> gated_event;
  };
  Anchor& Find(int anchor_id);
  AttemptOutcome Outcome(int anchor_id, const estimator::AnchorInitializer& initializer,
                         const std::optional<estimator::InitEvent>& event, const AnchorTruth* truth) const;

  estimator::InitializerOptions gated_options_;
  estimator::InitializerOptions fixed_options_;
  std::shared_ptr<const estimator::Solver> solver_;  // shared by all anchors: Solve is const
  std::map<int, Anchor> anchors_;
};

}  // namespace anchorbench::experiments
