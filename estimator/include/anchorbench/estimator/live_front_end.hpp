#pragma once

#include <condition_variable>
#include <cstddef>
#include <limits>
#include <mutex>
#include <set>
#include <vector>

#include "anchorbench/estimator/front_end.hpp"

namespace anchorbench::estimator {

// The front end for a live stack with several threads: a FrontEnd behind one lock, with its solves
// always deferred and run outside that lock.
//
// - Any thread may call any method (sensor callbacks, a solver worker, a service handler).
// - Adding a pose or a range takes the lock for O(1) work and never waits for a solve: a solve
//   holds the lock only to take its work and to hand back its result (FrontEnd::TakePendingSolve /
//   CompletePendingSolve), and runs the O(N) evaluation and solve between the two, unlocked.
// - Solves run where the caller runs RunPendingSolves(max_count, deadline): a worker thread, a
//   timer, or the adding thread itself. Several workers may run at once, each on another chain.
// - Events come out in the order their chains completed, each chain's in time order.
// - The results are those of a FrontEnd with deferred solves fed the same calls in the order the
//   lock took them, and so those of inline solves (AnchorInitializer's contract).
// Observers set on the FrontEnd run under the lock: they must not call back into this object.
class LiveFrontEnd {
 public:
  using Clock = FrontEnd::Clock;

  LiveFrontEnd(FrontEnd::ChainFactory factory, FrontEndOptions options);

  bool AddAnchor(int anchor_id);
  void AddPose(double t_s, int tag_id, const Eigen::Vector3d& p_world_tag);
  void AddRange(double t_s, int tag_id, int anchor_id, double range_m);
  void AddSample(const RangeSample& sample);

  // Runs due solves outside the lock: at most `max_count`, none started after `deadline`.
  // Returns the number run.
  std::size_t RunPendingSolves(std::size_t max_count = std::numeric_limits<std::size_t>::max(),
                               Clock::time_point deadline = Clock::time_point::max());
  std::size_t pending_solves() const;
  std::vector<FrontEndEvent> TakeEvents();

  // End of data: waits for the solves running on other threads, then FrontEnd::Finish.
  void Finish(double t_end_s);
  // Starts one anchor over (FrontEnd::ResetAnchor), or every anchor known; waits for the
  // anchor's running solves first. False if the anchor is unknown.
  bool ResetAnchor(int anchor_id);
  void ResetAll();

  FrontEndCounters counters() const;
  std::vector<int> anchor_ids() const;
  // Reads the front end under the lock (e.g. an anchor's chains for a status report): `read`
  // must not keep references past the call.
  template <typename Read>
  auto Inspect(Read&& read) const {
    std::lock_guard lock(mutex_);
    return read(static_cast<const FrontEnd&>(front_end_));
  }
  template <typename Change>
  void Configure(Change&& configure) {  // e.g. SetDropObserver
    std::lock_guard lock(mutex_);
    configure(front_end_);
  }

 private:
  void WaitForAnchor(std::unique_lock<std::mutex>& lock, int anchor_id);

  mutable std::mutex mutex_;
  std::condition_variable solve_done_;
  FrontEnd front_end_;
  std::multiset<int> working_;  // anchors with a solve running outside the lock
};

}  // namespace anchorbench::estimator
