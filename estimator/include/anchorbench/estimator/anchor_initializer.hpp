#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/closest_point_pdop.hpp"
#include "anchorbench/estimator/consistency_filter.hpp"
#include "anchorbench/estimator/range_sample.hpp"

namespace anchorbench::estimator {

enum class InitStrategy {
  kPdopGated,    // Sec. III-C: initialize once the closest-point PDOP drops below the threshold
  kFixedWindow,  // Sec. IV-A baseline: solve once on all of the anchor's data, at Finish()
};

struct InitializerOptions {
  InitStrategy strategy = InitStrategy::kPdopGated;
  ConsistencyFilterOptions filter;
  double pdop_threshold = 1.0;  // Sec. IV-A uses 1
  int min_samples = 20;         // accepted samples needed before the trigger may fire
  // After a failed solve (degenerate or non-finite), retry once the accepted data has grown by
  // this factor, so a bad geometry does not cost a solve per sample.
  double retry_growth = 1.2;
  AnchorSolverOptions solver;
  // A solver registry name (SolverRegistry); resolved by whoever owns the registry. The
  // initializer itself uses the solver it is given, or lm_adaptive built from `solver`.
  std::string solver_name = "lm_adaptive";

  bool IsValid(std::string* why) const;
};

// The outcome of an initialization: when, on how much data, and the solver's summary.
struct InitEvent {
  int anchor_id = 0;
  double t_s = 0.0;
  int n_used = 0;
  double pdop_estimate = 0.0;  // closest-point PDOP at that moment
  SolveResult solve;
};

// What Feed() reports for every sample, for traces.
struct FeedResult {
  bool accepted = false;
  int n_accepted = 0;
  double pdop = 0.0;                 // closest-point PDOP after this sample (+inf if undefined)
  std::optional<InitEvent> event;  // set on the sample that initialized the anchor (gated only)
};

// Online initializer for one anchor (Fig. 2): consistency filter -> closest-point PDOP trigger ->
// LS -> NLS. Fed one sample at a time in time order; no I/O, no global state, so a navigation
// stack can own one per anchor. After a gated initialization the filter and the PDOP keep
// updating (for traces) but no more data is buffered.
class AnchorInitializer {
 public:
  // With the paper's solver (LS + adaptive LM from options.solver), or with any other one.
  AnchorInitializer(int anchor_id, const InitializerOptions& options);
  AnchorInitializer(int anchor_id, const InitializerOptions& options, std::shared_ptr<const Solver> solver);

  FeedResult Feed(const RangeSample& sample);

  // End of data. Fixed window: solves on everything accepted (returns the event, or an event
  // with a failure status). Gated: returns nothing; the event, if any, came from Feed.
  std::optional<InitEvent> Finish(double t_s);

  bool initialized() const { return initialized_; }
  int anchor_id() const { return anchor_id_; }
  // Accepted data so far (for gated: up to the initialization).
  std::span<const Eigen::Vector3d> p_world_tag() const { return p_world_tag_; }
  std::span<const double> range_m() const { return range_m_; }
  const ClosestPointPdop& pdop() const { return pdop_; }
  // The latest gated solve that failed (degenerate, non-finite), if any: why it is not initialized.
  const std::optional<SolveResult>& last_failed_solve() const { return last_failed_solve_; }

 private:
  InitEvent SolveNow(double t_s);

  int anchor_id_;
  InitializerOptions options_;
  ConsistencyFilter filter_;
  ClosestPointPdop pdop_;
  std::shared_ptr<const Solver> solver_;
  std::vector<Eigen::Vector3d> p_world_tag_;
  std::vector<double> range_m_;
  bool initialized_ = false;
  std::size_t next_attempt_size_ = 0;
  std::optional<SolveResult> last_failed_solve_;
};

}  // namespace anchorbench::estimator
