#pragma once

#include <cstddef>
#include <deque>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "anchorbench/estimator/enum_names.hpp"
#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/closest_point_pdop.hpp"
#include "anchorbench/estimator/consistency_filter.hpp"
#include "anchorbench/estimator/credible_covariance.hpp"
#include "anchorbench/estimator/height_check.hpp"
#include "anchorbench/estimator/init_trigger.hpp"
#include "anchorbench/estimator/outlier_filter.hpp"
#include "anchorbench/estimator/range_sample.hpp"
#include "anchorbench/estimator/tag_biases.hpp"

namespace anchorbench::estimator {

// What an initializer does when its buffer of accepted samples is full.
enum class BufferPolicy {
  kThin,       // drop every second buffered sample and from then on buffer every 2nd accepted one
               // (then every 4th, ...): the buffer keeps spanning the whole run, at a coarser rate
  kKeepFirst,  // stop buffering: solves use the first max_buffered_samples accepted samples
};
inline constexpr EnumNames<BufferPolicy, 2> kBufferPolicyNames({
    {BufferPolicy::kThin, "thin"}, {BufferPolicy::kKeepFirst, "keep_first"}});
inline std::string_view ToString(BufferPolicy value) { return kBufferPolicyNames.Name(value); }
inline bool ParseBufferPolicy(std::string_view name, BufferPolicy* value) { return kBufferPolicyNames.Parse(name, value); }

struct InitializerOptions {
  int min_samples = 20;  // accepted samples needed before any trigger may fire (ours; the paper gives none)
  // After a failed solve (degenerate or non-finite), retry once the accepted data has grown by
  // this factor, so a bad geometry does not cost a solve per sample.
  double retry_growth = 1.2;
  // The memory bound of one initializer: at most this many samples (36 bytes each) are kept for
  // the solve, whatever the run's length; the closest-point PDOP still counts every sample. The
  // default holds 80 minutes of one tag at 10 Hz, beyond every committed experiment (largest:
  // 6002 samples), so it changes none of their numbers.
  int max_buffered_samples = 50000;
  BufferPolicy at_cap = BufferPolicy::kThin;
  // Off by default (the paper has none): every solve of the initializer, after its filter, must
  // beat its mirror through the tags' plane, else it counts as failed (height_unobservable).
  HeightCheckOptions height_check;
  // What every solve's covariance adds beyond the solver's noise-only one (credible_covariance.hpp).
  CovarianceOptions covariance;
  // One bias per tag, with two or more tags (tag_biases.hpp).
  TagBiasOptions tag_biases;

  bool IsValid(std::string* why) const;
};

// The outcome of an initialization: when, on how much data, and the solver's summary.
struct InitEvent {
  int anchor_id = 0;
  double t_s = 0.0;
  int n_used = 0;              // samples in the solve
  double pdop_closest_point = 0.0;  // Eq. (4) when the trigger fired (fixed window: at the end), not at the estimate
  SolveResult solve;
};

// What Feed() reports for every sample, for traces.
struct FeedResult {
  bool accepted = false;
  int n_accepted = 0;  // every sample the filter accepted so far (those in the PDOP)
  double pdop = 0.0;               // closest-point PDOP after this sample (+inf if undefined)
  std::optional<InitEvent> event;  // set on the sample that initialized the anchor (inline solves)
  bool solve_pending = false;      // deferred solves: a solve waits for RunPendingSolve()
};

// The work of a pending solve: the trigger's evaluation and, if it said solve, the solve.
struct PendingWork {
  bool solved = false;  // false: the trigger's evaluation did not fire (event unset)
  InitEvent event;
};

// Online initializer for one anchor (Fig. 2): filter -> trigger -> solver. Fed one sample at a
// time in time order; no I/O, no global state, bounded memory, so a navigation stack can own one
// per anchor. The closest-point PDOP is kept for every trigger (traces, reports). After an online
// initialization the filter and the PDOP keep updating but no more data is buffered.
//
// Solves run inside Feed() by default. With SetDeferSolves(true), Feed() is O(1) and allocation-
// free apart from its queue: a trigger that fires (or, for a trigger that solves, whose cadence is
// due: InitTrigger::Evaluate) leaves a solve pending, later samples are queued, and
// RunPendingSolve() runs the evaluation and the solve when the caller likes, then catches up on
// the queued samples. The results are identical to solving inline (tested).
//
// Threading: not thread-safe. One thread, the owner, makes every call, with one exception: while
// a solve is pending, WorkPendingSolve() may run on one other thread while the owner goes on
// calling Feed(); the owner then hands its result to CompletePendingSolve() and makes no other
// call in between. The work reads only the frozen buffer, the trigger (which sees no call while a
// solve is pending), the const solver and the filter's TravelBias(); Feed() touches only the
// filter's online stage, the PDOP and the queue. Initializers share nothing mutable (solvers are
// const, kernel tables immutable), so distinct initializers may each live on their own thread.
//
// Memory: at most max_buffered_samples samples buffered (36 bytes each, reserved when the
// initializer is made: address space until written, never reallocated) plus as many queued behind
// a deferred solve (56 bytes each): at most ~4.6 MB at the default cap, whatever the run's length.
class AnchorInitializer {
 public:
  AnchorInitializer(int anchor_id, const InitializerOptions& options, std::unique_ptr<OutlierFilter> filter,
                    std::unique_ptr<InitTrigger> trigger, std::shared_ptr<const Solver> solver);

  FeedResult Feed(const RangeSample& sample);

  void SetDeferSolves(bool defer) { defer_solves_ = defer; }
  bool solve_pending() const { return pending_.has_value(); }
  // Runs the pending solve; the event if it initialized the anchor. After a failed solve (or an
  // evaluation that did not fire) the queued samples are fed to the trigger, which may leave
  // another solve pending. RunPendingSolve() is CompletePendingSolve(WorkPendingSolve()).
  std::optional<InitEvent> RunPendingSolve();
  // The two halves, for a solve on a worker thread (see Threading above). WorkPendingSolve()
  // requires solve_pending().
  PendingWork WorkPendingSolve();
  std::optional<InitEvent> CompletePendingSolve(const PendingWork& work);

  // End of data. Pending solves run first (their event, if one initializes). An offline trigger
  // (fixed window) then solves on everything buffered and returns the event, possibly with a
  // failure status, at the time of its last admitted sample (t_s only if it has none). Online
  // triggers return nothing here when their event came from Feed().
  std::optional<InitEvent> Finish(double t_s);

  bool initialized() const { return initialized_; }
  int anchor_id() const { return anchor_id_; }
  bool online() const { return trigger_->online(); }
  // The buffered data (online triggers: up to the initialization).
  std::span<const Eigen::Vector3d> p_world_tag() const { return p_world_tag_; }
  std::span<const double> range_m() const { return range_m_; }
  std::span<const int> tag_id() const { return tag_id_; }
  const ClosestPointPdop& pdop() const { return pdop_; }
  // The latest online solve that failed (degenerate, non-finite, a mirror), if any, with when it
  // ran: why the anchor is not initialized.
  const std::optional<InitEvent>& last_failed_solve() const { return last_failed_solve_; }
  // The trigger's reason for not firing, where it has one (InitTrigger::refusal).
  std::optional<SolveStatus> trigger_refusal() const { return trigger_->refusal(); }
  // Why the anchor is not initialized yet: too few samples ("samples": n against min_samples),
  // waiting for more data after a failed solve ("retry": n against the size of the next attempt),
  // else the trigger's own test (InitTrigger::why_not). Nothing once initialized, or for a trigger
  // without a test.
  std::optional<Judgement> why_not() const;
  // Where to range from next (guidance.hpp): the trigger's region forecast from every buffered
  // sample, at its last evaluation's estimate. O(N) to build, O(1) per candidate. Nothing once
  // initialized, or where the trigger has no region basis (not certified, or its last evaluation
  // had no estimate).
  std::optional<RegionForecast> Forecast() const;
  // The judgement of an evaluation of the trigger that has run since the last call, if one has
  // (a trigger that solves judges on its cadence: one evaluation per pending solve).
  std::optional<Judgement> TakeJudgement();
  // Accepted samples left out of the buffer by its cap, and samples lost because the queue behind
  // a deferred solve reached the cap (the solve was not run in time).
  long samples_not_buffered() const { return samples_not_buffered_; }
  long samples_dropped_while_pending() const { return samples_dropped_while_pending_; }

 private:
  struct Accepted {
    double t_s;
    int tag_id;
    Eigen::Vector3d p_world_tag;
    double range_m;
    double pdop;  // closest-point PDOP right after this sample
  };

  void Admit(const Accepted& sample);  // buffer it and ask the trigger
  void Buffer(int tag_id, const Eigen::Vector3d& p_world_tag, double range_m);
  InitEvent SolveNow(double t_s, double pdop) const;

  int anchor_id_;
  InitializerOptions options_;
  std::unique_ptr<OutlierFilter> filter_;
  std::unique_ptr<InitTrigger> trigger_;
  std::shared_ptr<const Solver> solver_;  // as the filter's solve stage hands it back, mirror-checked
  ClosestPointPdop pdop_;
  std::vector<Eigen::Vector3d> p_world_tag_;
  std::vector<double> range_m_;
  std::vector<int> tag_id_;
  std::size_t n_admitted_ = 0;   // samples the trigger has seen
  std::size_t keep_every_ = 1;   // BufferPolicy::kThin: buffer every keep_every_-th admitted sample
  double t_first_s_ = 0.0, t_last_s_ = 0.0;  // of the first and the latest admitted sample
  bool initialized_ = false;
  std::size_t next_attempt_size_ = 0;
  std::optional<InitEvent> last_failed_solve_;
  bool defer_solves_ = false;
  std::optional<TriggerInput> pending_;  // what the trigger fired on; the buffer stays as it saw it
  std::deque<Accepted> queued_;  // accepted while a deferred solve was pending
  long samples_not_buffered_ = 0;
  long samples_dropped_while_pending_ = 0;
  std::size_t judgements_taken_ = 0;  // the trigger's evaluations already handed out
};

// The paper's chain with typed options: the consistency check (Sec. III-B), the closest-point
// PDOP trigger (Sec. III-C) and LS + adaptive-kernel NLS (Sec. III-D).
struct PaperChainOptions {
  InitializerOptions initializer;
  ConsistencyFilterOptions filter;
  double pdop_threshold = 1.0;
  AnchorSolverOptions solver;
};
AnchorInitializer MakePaperInitializer(int anchor_id, const PaperChainOptions& options = {},
                                       std::shared_ptr<const LogPartitionTable> table = nullptr);

}  // namespace anchorbench::estimator
