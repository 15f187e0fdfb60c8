#include "anchorbench/estimator/live_front_end.hpp"

#include <utility>

namespace anchorbench::estimator {
namespace {

FrontEndOptions Deferred(FrontEndOptions options) {
  options.defer_solves = true;  // no solve inside an add, whichever thread adds
  return options;
}

}  // namespace

LiveFrontEnd::LiveFrontEnd(FrontEnd::ChainFactory factory, FrontEndOptions options)
    : front_end_(std::move(factory), Deferred(std::move(options))) {}

bool LiveFrontEnd::AddAnchor(int anchor_id) {
  std::lock_guard lock(mutex_);
  return front_end_.AddAnchor(anchor_id);
}

void LiveFrontEnd::AddPose(double t_s, int tag_id, const Eigen::Vector3d& p_world_tag) {
  std::lock_guard lock(mutex_);
  front_end_.AddPose(t_s, tag_id, p_world_tag);
}

void LiveFrontEnd::AddRange(double t_s, int tag_id, int anchor_id, double range_m) {
  std::lock_guard lock(mutex_);
  front_end_.AddRange(t_s, tag_id, anchor_id, range_m);
}

void LiveFrontEnd::AddSample(const RangeSample& sample) {
  std::lock_guard lock(mutex_);
  front_end_.AddSample(sample);
}

std::size_t LiveFrontEnd::RunPendingSolves(std::size_t max_count, Clock::time_point deadline) {
  std::size_t solved = 0;
  while (solved < max_count && (deadline == Clock::time_point::max() || Clock::now() < deadline)) {
    std::optional<FrontEnd::PendingSolve> solve;
    {
      std::lock_guard lock(mutex_);
      solve = front_end_.TakePendingSolve();
      if (!solve) break;
      working_.insert(solve->anchor_id);
    }
    PendingWork work;
    try {
      work = FrontEnd::WorkPendingSolve(*solve);  // unlocked: the chain queues what arrives meanwhile
    } catch (...) {
      std::lock_guard lock(mutex_);
      front_end_.CompletePendingSolve(*solve, PendingWork{});  // as if the evaluation had not fired
      working_.erase(working_.find(solve->anchor_id));
      solve_done_.notify_all();
      throw;
    }
    {
      std::lock_guard lock(mutex_);
      front_end_.CompletePendingSolve(*solve, work);
      working_.erase(working_.find(solve->anchor_id));
    }
    solve_done_.notify_all();
    ++solved;
  }
  return solved;
}

std::size_t LiveFrontEnd::pending_solves() const {
  std::lock_guard lock(mutex_);
  return front_end_.pending_solves();
}

std::vector<FrontEndEvent> LiveFrontEnd::TakeEvents() {
  std::lock_guard lock(mutex_);
  return front_end_.TakeEvents();
}

void LiveFrontEnd::WaitForAnchor(std::unique_lock<std::mutex>& lock, int anchor_id) {
  solve_done_.wait(lock, [&] { return !working_.contains(anchor_id); });
}

void LiveFrontEnd::Finish(double t_end_s) {
  std::unique_lock lock(mutex_);
  solve_done_.wait(lock, [&] { return working_.empty(); });
  front_end_.Finish(t_end_s);
}

bool LiveFrontEnd::ResetAnchor(int anchor_id) {
  std::unique_lock lock(mutex_);
  WaitForAnchor(lock, anchor_id);
  return front_end_.ResetAnchor(anchor_id);
}

void LiveFrontEnd::ResetAll() {
  std::unique_lock lock(mutex_);
  solve_done_.wait(lock, [&] { return working_.empty(); });
  for (const int anchor_id : front_end_.anchor_ids()) front_end_.ResetAnchor(anchor_id);
}

FrontEndCounters LiveFrontEnd::counters() const {
  std::lock_guard lock(mutex_);
  return front_end_.counters();
}

std::vector<int> LiveFrontEnd::anchor_ids() const {
  std::lock_guard lock(mutex_);
  return front_end_.anchor_ids();
}

}  // namespace anchorbench::estimator
