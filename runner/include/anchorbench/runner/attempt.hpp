#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "anchorbench/estimator/anchor_initializer.hpp"
#include "anchorbench/eval/attempt_evaluation.hpp"

namespace anchorbench::runner {

// One anchor with one trigger (a `method`) in one realization of one row: what happened, and how
// good it was where the truth is known. A row of attempts.csv (run) and of estimates.csv (replay).
struct Attempt {
  int row = 0;
  int realization = 0;
  int anchor_id = 0;
  std::string method;  // the trigger's name (fixed_window, pdop_closest_point, ...)
  bool initialized = false;
  std::optional<double> t_init_s;  // when the solve ran (online: the trigger; fixed: end of data)
  int n_used = 0;                  // samples in the solve, or buffered so far if none ran
  double pdop_estimate = 0.0;      // closest-point PDOP at that moment (+inf if undefined)
  std::optional<estimator::SolveResult> solve;  // absent if the solver never ran
  std::string status;                           // the solver's, or not_triggered / no_data
  std::optional<eval::AttemptEvaluation> evaluation;  // where the truth is known
  std::optional<double> crlb_m;  // sigma_d times the bias-aware DOP (simulations, where sigma_d is known)
  // Wall time of this trigger's pass over all of the realization's samples (filter, PDOP,
  // trigger, solves) divided by the number of anchors. Varies from run to run, so it goes to
  // timing files only, never into the deterministic tables.
  double compute_s = 0.0;
};

// The attempt of one of an anchor's initializers, after the end of data: `event` is its
// initialization (or its fixed-window solve), if any; `truth` (may be null) adds the evaluation.
Attempt AttemptOf(const estimator::AnchorInitializer& initializer, const std::optional<estimator::InitEvent>& event,
                  const std::string& method, const eval::AnchorTruth* truth);

// The seed of anchor `anchor_id`'s random parts (RANSAC) in realization `realization`: drawn from
// the stream (seed, realization, kSolverStream, anchor id), so it repeats for any thread count.
constexpr std::uint32_t kSolverStream = 8;  // sim::kFirstFreeStreamId: the ids below are sim's
std::uint64_t SolverSeed(std::uint64_t seed, std::uint64_t realization, int anchor_id);

// The truth of one anchor, or nullptr.
const eval::AnchorTruth* TruthOf(const std::map<int, eval::AnchorTruth>* truth, int anchor_id);

}  // namespace anchorbench::runner
