#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "anchorbench/estimator/anchor_initializer.hpp"
#include "anchorbench/estimator/components.hpp"
#include "anchorbench/experiments/recorded_data.hpp"

namespace anchorbench::experiments {

// The built-in solvers, filters and triggers, registered once.
const estimator::Components& BuiltinComponents();

// One anchor, one trigger: what happened, and how good it was when the truth is known.
struct AttemptOutcome {
  int anchor_id = 0;
  std::string method;               // the trigger's name (fixed_window, pdop_closest_point, ...)
  bool initialized = false;
  std::optional<double> t_init_s;   // when the solve ran (online: the trigger; fixed: end of data)
  int n_used = 0;                   // samples in the solve, or accepted so far if none ran
  double pdop_estimate = 0.0;       // closest-point PDOP at that moment (+inf if undefined)
  std::optional<double> pdop_true;  // Eq. (2)-(3) at the true anchor on the same samples
  std::optional<double> bias_aware_dop;  // sigma_d times this is the CRLB on the position error
  std::optional<estimator::SolveResult> solve;  // absent if the solver never ran
  std::optional<double> error_m;    // ||estimate - truth|| for initialized attempts with truth
  // Wall time of this trigger's pass over all of the run's samples (filter, PDOP, trigger, solves)
  // divided by the number of anchors: sums to the trigger's total. Varies from run to run, so it
  // goes to timing files only, never into the deterministic tables.
  double compute_s = 0.0;
};

// For every anchor, one initializer per trigger in options.triggers, all fed the same
// time-ordered samples (simulated or recorded).
class AnchorBank {
 public:
  // Parts come from `components` (default: the built-ins). Anchor a's random parts are seeded by
  // the stream (seed, realization, kSolver, a). `truth` (may be null) serves the pdop_true oracle
  // and the evaluation columns. Throws InputError if a part cannot be built for an anchor.
  AnchorBank(const estimator::InitializerOptions& options, std::uint64_t seed, std::uint64_t realization,
             const std::map<int, AnchorTruth>* truth, const estimator::Components* components = nullptr);

  // Makes the anchor known before its first range, so it is reported even if none arrives.
  void AddAnchor(int anchor_id);

  // Called for every sample with the first trigger's view of it (filter and closest-point PDOP
  // are the same for every trigger).
  using Trace = std::function<void(std::size_t sample_index, const estimator::FeedResult&)>;

  // Runs each trigger's initializers over all samples, one trigger after the other (so each
  // trigger's compute time is measured without clock reads per sample), then ends the data at
  // t_end_s. One outcome per anchor and trigger: anchor ids ascending, triggers in list order.
  std::vector<AttemptOutcome> Run(std::span<const estimator::RangeSample> samples, double t_end_s,
                                  const Trace& trace = nullptr);

 private:
  struct Anchor {
    int id = 0;
    std::vector<estimator::AnchorInitializer> by_trigger;
    std::vector<std::optional<estimator::InitEvent>> events;
  };
  Anchor& Find(int anchor_id);  // built on first use
  AttemptOutcome Outcome(const Anchor& anchor, std::size_t trigger) const;

  estimator::InitializerOptions options_;
  std::uint64_t seed_;
  std::uint64_t realization_;
  const std::map<int, AnchorTruth>* truth_;
  const estimator::Components* components_;
  std::map<int, Anchor> anchors_;  // by id, so outcomes come out ascending
};

}  // namespace anchorbench::experiments
