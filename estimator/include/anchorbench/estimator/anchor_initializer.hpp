#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/closest_point_pdop.hpp"
#include "anchorbench/estimator/filter_registry.hpp"
#include "anchorbench/estimator/init_trigger.hpp"
#include "anchorbench/estimator/range_sample.hpp"

namespace anchorbench::estimator {

struct InitializerOptions {
  FilterOptions filter;
  TriggerOptions trigger;
  int min_samples = 20;  // accepted samples needed before any trigger may fire
  // After a failed solve (degenerate or non-finite), retry once the accepted data has grown by
  // this factor, so a bad geometry does not cost a solve per sample.
  double retry_growth = 1.2;
  AnchorSolverOptions solver;
  // Registry names, resolved by whoever owns the registries (MakeInitializer): the solver, and the
  // triggers an experiment runs side by side on the same data, one initializer each. The filter's
  // name is filter.kind.
  std::string solver_name = "lm_adaptive";
  std::vector<std::string> triggers = {"fixed_window", "pdop_closest_point"};

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
  double pdop = 0.0;               // closest-point PDOP after this sample (+inf if undefined)
  std::optional<InitEvent> event;  // set on the sample that initialized the anchor (online triggers)
};

// Online initializer for one anchor (Fig. 2): filter -> trigger -> solver. Fed one sample at a
// time in time order; no I/O, no global state, so a navigation stack can own one per anchor. The
// closest-point PDOP is kept for every trigger (traces, reports). After an online initialization
// the filter and the PDOP keep updating but no more data is buffered.
class AnchorInitializer {
 public:
  // The paper's chain: consistency check (options.filter.consistency), closest-point PDOP trigger
  // (options.trigger.pdop_threshold), LS + adaptive NLS (options.solver).
  explicit AnchorInitializer(int anchor_id, const InitializerOptions& options = {});
  // Any chain (MakeInitializer builds one from registry names).
  AnchorInitializer(int anchor_id, const InitializerOptions& options, std::unique_ptr<OutlierFilter> filter,
                    std::unique_ptr<InitTrigger> trigger, std::shared_ptr<const Solver> solver);

  FeedResult Feed(const RangeSample& sample);

  // End of data. An offline trigger (fixed window) solves on everything accepted and returns the
  // event, possibly with a failure status. Online triggers return nothing; their event came from Feed.
  std::optional<InitEvent> Finish(double t_s);

  bool initialized() const { return initialized_; }
  int anchor_id() const { return anchor_id_; }
  // Accepted data so far (online triggers: up to the initialization).
  std::span<const Eigen::Vector3d> p_world_tag() const { return p_world_tag_; }
  std::span<const double> range_m() const { return range_m_; }
  const ClosestPointPdop& pdop() const { return pdop_; }
  // The latest online solve that failed (degenerate, non-finite), if any: why it is not initialized.
  const std::optional<SolveResult>& last_failed_solve() const { return last_failed_solve_; }

 private:
  InitEvent SolveNow(double t_s);

  int anchor_id_;
  InitializerOptions options_;
  std::unique_ptr<OutlierFilter> filter_;
  std::unique_ptr<InitTrigger> trigger_;
  std::shared_ptr<const Solver> solver_;  // as the filter's solve stage hands it back
  ClosestPointPdop pdop_;
  std::vector<Eigen::Vector3d> p_world_tag_;
  std::vector<double> range_m_;
  double t_first_s_ = 0.0;
  bool initialized_ = false;
  std::size_t next_attempt_size_ = 0;
  std::optional<SolveResult> last_failed_solve_;
};

}  // namespace anchorbench::estimator
