#include "anchorbench/estimator/front_end.hpp"

#include <algorithm>

namespace anchorbench::estimator {

FrontEnd::FrontEnd(ChainFactory factory, const FrontEndOptions& options)
    : factory_(std::move(factory)), options_(options), poses_(options.poses) {}

std::vector<AnchorInitializer> FrontEnd::MakeChains(int anchor_id) {
  std::vector<AnchorInitializer> chains = factory_(anchor_id);
  for (AnchorInitializer& chain : chains) chain.SetDeferSolves(options_.defer_solves);
  return chains;
}

std::vector<AnchorInitializer>& FrontEnd::Anchor(int anchor_id) {
  if (const auto found = anchors_.find(anchor_id); found != anchors_.end()) return found->second;
  return anchors_.emplace(anchor_id, MakeChains(anchor_id)).first->second;
}

bool FrontEnd::ResetAnchor(int anchor_id) {
  const auto found = anchors_.find(anchor_id);
  if (found == anchors_.end()) return false;
  std::erase_if(pending_, [anchor_id](const std::pair<int, std::size_t>& p) { return p.first == anchor_id; });
  found->second = MakeChains(anchor_id);
  return true;
}

bool FrontEnd::AddAnchor(int anchor_id) {
  if (!anchors_.contains(anchor_id) && anchors_.size() >= options_.max_anchors) return false;
  Anchor(anchor_id);
  return true;
}

void FrontEnd::Emit(int anchor_id, std::size_t chain, const InitEvent& event) {
  FrontEndEvent initialized;
  initialized.anchor_id = anchor_id;
  initialized.chain = chain;
  initialized.init = event;
  events_.push_back(std::move(initialized));
}

void FrontEnd::EmitJudgement(int anchor_id, std::size_t chain, AnchorInitializer& initializer) {
  if (!options_.report_judgements) return;
  if (std::optional<Judgement> judged = initializer.TakeJudgement()) {
    FrontEndEvent judged_event;
    judged_event.anchor_id = anchor_id;
    judged_event.chain = chain;
    judged_event.init.anchor_id = anchor_id;
    judged_event.kind = FrontEndEvent::Kind::kJudged;
    judged_event.judgement = *judged;
    events_.push_back(std::move(judged_event));
  }
}

void FrontEnd::Drop(const WaitingRange& range, DroppedRange::Reason reason) {
  switch (reason) {
    case DroppedRange::Reason::kOutsidePoses: ++counters_.ranges_outside_poses; break;
    case DroppedRange::Reason::kNoPoseInTime: ++counters_.ranges_without_pose; break;
    case DroppedRange::Reason::kTooManyAnchors: ++counters_.ranges_beyond_max_anchors; break;
  }
  if (drop_observer_) drop_observer_({range.t_s, range.tag_id, range.anchor_id, range.range_m, reason});
}

void FrontEnd::Feed(const RangeSample& sample) {
  if (!anchors_.contains(sample.anchor_id) && anchors_.size() >= options_.max_anchors) {
    Drop({sample.t_s, sample.tag_id, sample.anchor_id, sample.range_m}, DroppedRange::Reason::kTooManyAnchors);
    return;
  }
  std::vector<AnchorInitializer>& chains = Anchor(sample.anchor_id);
  ++counters_.samples;
  t_last_sample_s_ = sample.t_s;
  for (std::size_t c = 0; c < chains.size(); ++c) {
    const bool was_pending = chains[c].solve_pending();
    const FeedResult fed = chains[c].Feed(sample);
    EmitJudgement(sample.anchor_id, c, chains[c]);
    if (fed.event) Emit(sample.anchor_id, c, *fed.event);
    if (fed.solve_pending && !was_pending) pending_.emplace_back(sample.anchor_id, c);
    if (c == 0 && observer_) observer_(sample, fed);
  }
}

void FrontEnd::AddSample(const RangeSample& sample) {
  t_latest_s_ = std::max(t_latest_s_, sample.t_s);
  Feed(sample);
}

void FrontEnd::AddPose(double t_s, int tag_id, const Eigen::Vector3d& p_world_tag) {
  if (!poses_.Add(tag_id, t_s, p_world_tag)) {
    ++counters_.poses_ignored;
    return;
  }
  t_latest_s_ = std::max(t_latest_s_, t_s);
  ReleaseWaiting();
}

void FrontEnd::AddRange(double t_s, int tag_id, int anchor_id, double range_m) {
  t_latest_s_ = std::max(t_latest_s_, t_s);
  if (waiting_.size() >= options_.max_waiting_ranges) {
    Drop(waiting_.front(), DroppedRange::Reason::kNoPoseInTime);
    waiting_.pop_front();
  }
  waiting_.push_back({t_s, tag_id, anchor_id, range_m});  // behind any earlier one: time order holds
  ReleaseWaiting();
}

// Ranges leave the queue in arrival order, each once its tag's poses reach its time.
void FrontEnd::ReleaseWaiting() {
  while (!waiting_.empty()) {
    const WaitingRange range = waiting_.front();
    Eigen::Vector3d p_world_tag;
    const PoseBuffer::Lookup lookup = poses_.At(range.tag_id, range.t_s, &p_world_tag);
    if (lookup == PoseBuffer::Lookup::kNotYet && t_latest_s_ - range.t_s <= options_.max_wait_s) return;
    waiting_.pop_front();
    if (lookup == PoseBuffer::Lookup::kFound) {
      Feed({range.t_s, range.tag_id, range.anchor_id, range.range_m, p_world_tag});
    } else {
      Drop(range, lookup == PoseBuffer::Lookup::kOutside ? DroppedRange::Reason::kOutsidePoses
                                                          : DroppedRange::Reason::kNoPoseInTime);
    }
  }
}

std::optional<FrontEnd::PendingSolve> FrontEnd::TakePendingSolve() {
  if (pending_.empty()) return std::nullopt;
  const auto [anchor_id, chain] = pending_.front();
  pending_.pop_front();
  return PendingSolve{anchor_id, chain, &anchors_.at(anchor_id)[chain]};
}

void FrontEnd::CompletePendingSolve(const PendingSolve& solve, const PendingWork& work) {
  std::optional<InitEvent> event = solve.initializer->CompletePendingSolve(work);
  EmitJudgement(solve.anchor_id, solve.chain, *solve.initializer);
  if (event) Emit(solve.anchor_id, solve.chain, *event);
  // The catch-up on the samples queued meanwhile fired again: due once more, behind the others.
  if (solve.initializer->solve_pending()) pending_.emplace_back(solve.anchor_id, solve.chain);
}

std::size_t FrontEnd::RunPendingSolves(std::size_t max_count, Clock::time_point deadline) {
  std::size_t solved = 0;
  while (solved < max_count && (deadline == Clock::time_point::max() || Clock::now() < deadline)) {
    const std::optional<PendingSolve> solve = TakePendingSolve();
    if (!solve) break;
    CompletePendingSolve(*solve, WorkPendingSolve(*solve));
    ++solved;
  }
  return solved;
}

std::vector<FrontEndEvent> FrontEnd::TakeEvents() {
  std::vector<FrontEndEvent> events;
  events.swap(events_);
  return events;
}

void FrontEnd::Finish(double t_end_s) {
  // No pose will come: what waits behind a range of another tag is used if its pose is known.
  while (!waiting_.empty()) {
    const WaitingRange range = waiting_.front();
    waiting_.pop_front();
    Eigen::Vector3d p_world_tag;
    if (poses_.At(range.tag_id, range.t_s, &p_world_tag) == PoseBuffer::Lookup::kFound) {
      Feed({range.t_s, range.tag_id, range.anchor_id, range.range_m, p_world_tag});
    } else {
      Drop(range, DroppedRange::Reason::kOutsidePoses);
    }
  }
  RunPendingSolves();
  for (auto& [anchor_id, chains] : anchors_) {
    for (std::size_t c = 0; c < chains.size(); ++c) {
      std::optional<InitEvent> event = chains[c].Finish(t_end_s);
      EmitJudgement(anchor_id, c, chains[c]);
      if (event) Emit(anchor_id, c, *event);
    }
  }
}

std::vector<int> FrontEnd::anchor_ids() const {
  std::vector<int> ids;
  for (const auto& [id, chains] : anchors_) ids.push_back(id);
  return ids;
}

}  // namespace anchorbench::estimator
