#pragma once

#include <chrono>
#include <cstddef>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <vector>

#include "anchorbench/estimator/anchor_initializer.hpp"
#include "anchorbench/estimator/pose_buffer.hpp"

namespace anchorbench::estimator {

struct FrontEndOptions {
  PoseBufferOptions poses;
  // A range waits for a pose of its tag at or after its time; once the newest time seen anywhere
  // is this far past it, it is dropped and counted (a tag whose poses stopped or never came).
  double max_wait_s = 10.0;
  std::size_t max_waiting_ranges = 100000;  // beyond this, the oldest waiting range is dropped
  // Anchors tracked at most (each holds its chains' buffers): a range of a new anchor beyond this
  // is dropped and counted. Real deployments have tens; a log of a million ids is not one.
  std::size_t max_anchors = 1000;
  // Solves run when the caller calls RunPendingSolves() instead of inside AddRange/AddSample
  // (same results; see AnchorInitializer::SetDeferSolves).
  bool defer_solves = false;
  // Every evaluation of a trigger that solves (the certificate's among them) is also an event:
  // why the anchor is not initialized yet, as it was judged (a live "why not yet").
  bool report_judgements = false;
};

// An initialization (or a fixed-window solve at the end) of one anchor by one of its chains; with
// FrontEndOptions::report_judgements, also each evaluation of a trigger that solves.
struct FrontEndEvent {
  enum class Kind { kInitialized, kJudged };
  int anchor_id = 0;
  std::size_t chain = 0;  // index in the factory's list (e.g. the trigger)
  InitEvent init;         // kInitialized: when, on how many samples, the estimate with covariance and status, the PDOP
  Kind kind = Kind::kInitialized;
  Judgement judgement;    // kJudged: the trigger's tests as it judged them
};

// A range the front end could not hand to the initializers, and why.
struct DroppedRange {
  enum class Reason {
    kOutsidePoses,  // before the oldest pose kept, or after the tag's last pose at the end of data
    kNoPoseInTime,  // waited longer than max_wait_s, or the waiting queue was full
    kTooManyAnchors,  // a new anchor beyond FrontEndOptions::max_anchors
  };
  double t_s = 0.0;
  int tag_id = 0;
  int anchor_id = 0;
  double range_m = 0.0;
  Reason reason = Reason::kOutsidePoses;
};

// What the front end dropped before the initializers, by reason.
struct FrontEndCounters {
  long samples = 0;                 // ranges handed to the initializers
  long ranges_outside_poses = 0;    // before the oldest pose kept, or after the last at the end of data
  long ranges_without_pose = 0;     // waited longer than max_wait_s, or the waiting queue was full
  long poses_ignored = 0;           // time not increasing for the tag, or not finite
  long ranges_beyond_max_anchors = 0;  // of a new anchor beyond max_anchors
};

// The online front end of a navigation stack with many anchors and one sensor callback: fed tag
// poses and ranges as they arrive (or samples whose tag position is known), it interpolates the
// tag position at each range time, creates the anchor's initializers on first sight (one per
// chain: e.g. one per trigger), feeds them, and reports initializations as events. Memory is
// bounded: a sliding pose history, a bounded queue of ranges waiting for their pose, and each
// initializer's bounded buffer. No I/O, no global state.
//
// Threading: not thread-safe; one thread makes every call. With defer_solves, AddPose/AddRange/
// AddSample never solve (every trigger's O(N) evaluation waits too: InitTrigger::Evaluate), and
// RunPendingSolves() runs them where the caller likes, e.g. in an idle step of the same thread.
// LiveFrontEnd (live_front_end.hpp) is the thread-safe wrapper: any thread adds, and solves run
// outside its lock through TakePendingSolve / WorkPendingSolve / CompletePendingSolve.
//
// Memory: at most max_anchors anchors, each with its chains' bounded buffers (~4.6 MB per chain
// at most, at the default caps: AnchorInitializer), max_waiting_ranges waiting ranges (24 bytes each) and
// the pose history of PoseBufferOptions.
class FrontEnd {
 public:
  // The chains of a new anchor; may throw std::invalid_argument (the front end passes it on).
  using ChainFactory = std::function<std::vector<AnchorInitializer>(int anchor_id)>;
  // Sees every sample handed to the initializers, with the first chain's view of it.
  using SampleObserver = std::function<void(const RangeSample&, const FeedResult&)>;
  // Sees every range dropped. Ranges leave the waiting queue (used or dropped) in arrival order.
  using DropObserver = std::function<void(const DroppedRange&)>;

  explicit FrontEnd(ChainFactory factory, const FrontEndOptions& options = {});

  // Known before its first range, so it is reported even without one; false beyond max_anchors.
  bool AddAnchor(int anchor_id);
  void AddPose(double t_s, int tag_id, const Eigen::Vector3d& p_world_tag);
  void AddRange(double t_s, int tag_id, int anchor_id, double range_m);
  void AddSample(const RangeSample& sample);  // the tag position already known (e.g. simulation)

  using Clock = std::chrono::steady_clock;
  bool HasPendingSolves() const { return !pending_.empty(); }
  std::size_t pending_solves() const { return pending_.size(); }
  // Runs pending solves in the order they became due, at most `max_count`, and none started after
  // `deadline` (a solve is not interrupted: its own budget, NlsOptions::max_passes, bounds it).
  // Returns the number run.
  std::size_t RunPendingSolves(std::size_t max_count = std::numeric_limits<std::size_t>::max(),
                               Clock::time_point deadline = Clock::time_point::max());

  // A pending solve in three steps, for a caller that runs the work outside its own lock: Take
  // (O(1), removes it from the queue), Work (the O(N) evaluation and solve; on any thread, while
  // this front end goes on taking samples, since the chain queues them: anchor_initializer.hpp),
  // then Complete (emits the event; the chain's catch-up may leave it pending again). The chain's
  // address is stable for the front end's life, until ResetAnchor.
  struct PendingSolve {
    int anchor_id = 0;
    std::size_t chain = 0;
    AnchorInitializer* initializer = nullptr;
  };
  std::optional<PendingSolve> TakePendingSolve();
  static PendingWork WorkPendingSolve(const PendingSolve& solve) { return solve.initializer->WorkPendingSolve(); }
  void CompletePendingSolve(const PendingSolve& solve, const PendingWork& work);

  // Starts an anchor over: its chains made anew by the factory (its data, estimates and pending
  // solves gone), as if its first range came next. False if the anchor is unknown.
  bool ResetAnchor(int anchor_id);
  std::vector<FrontEndEvent> TakeEvents();

  // End of data at t_end_s: ranges still waiting are dropped (never extrapolated), pending solves
  // run, and offline chains (the fixed window) solve; their events join the others.
  void Finish(double t_end_s);

  void SetSampleObserver(SampleObserver observer) { observer_ = std::move(observer); }
  void SetDropObserver(DropObserver observer) { drop_observer_ = std::move(observer); }
  std::vector<int> anchor_ids() const;  // ascending
  const std::vector<AnchorInitializer>& chains(int anchor_id) const { return anchors_.at(anchor_id); }
  const FrontEndCounters& counters() const { return counters_; }
  double t_last_sample_s() const { return t_last_sample_s_; }

 private:
  struct WaitingRange {
    double t_s;
    int tag_id;
    int anchor_id;
    double range_m;
  };
  std::vector<AnchorInitializer> MakeChains(int anchor_id);
  std::vector<AnchorInitializer>& Anchor(int anchor_id);
  void Feed(const RangeSample& sample);
  void ReleaseWaiting();
  void Emit(int anchor_id, std::size_t chain, const InitEvent& event);
  void EmitJudgement(int anchor_id, std::size_t chain, AnchorInitializer& initializer);
  void Drop(const WaitingRange& range, DroppedRange::Reason reason);

  ChainFactory factory_;
  FrontEndOptions options_;
  PoseBuffer poses_;
  std::map<int, std::vector<AnchorInitializer>> anchors_;
  std::deque<WaitingRange> waiting_;
  std::deque<std::pair<int, std::size_t>> pending_;  // (anchor, chain) with a deferred solve
  std::vector<FrontEndEvent> events_;
  SampleObserver observer_;
  DropObserver drop_observer_;
  FrontEndCounters counters_;
  double t_latest_s_ = -std::numeric_limits<double>::infinity();  // newest time of any input
  double t_last_sample_s_ = 0.0;
};

}  // namespace anchorbench::estimator
