#include "anchorbench/estimator/anchor_initializer.hpp"

#include <cmath>

#include "anchorbench/estimator/consistency_filter.hpp"

namespace anchorbench::estimator {
bool InitializerOptions::IsValid(std::string* why) const {
  if (min_samples < 6) {
    if (why) *why = "min_samples must be >= 6 (4 unknowns, one pivot, one redundant row)";
    return false;
  }
  if (!(retry_growth > 1.0) || !std::isfinite(retry_growth)) {
    if (why) *why = "retry_growth must be > 1";
    return false;
  }
  return filter.IsValid(why) && trigger.IsValid(why) && solver.IsValid(why);
}

AnchorInitializer::AnchorInitializer(int anchor_id, const InitializerOptions& options)
    : AnchorInitializer(anchor_id, options, std::make_unique<ConsistencyFilter>(options.filter.consistency),
                        std::make_unique<ClosestPointPdopTrigger>(options.trigger.pdop_threshold),
                        std::make_shared<AnchorSolver>(options.solver)) {}

AnchorInitializer::AnchorInitializer(int anchor_id, const InitializerOptions& options,
                                     std::unique_ptr<OutlierFilter> filter, std::unique_ptr<InitTrigger> trigger,
                                     std::shared_ptr<const Solver> solver)
    : anchor_id_(anchor_id),
      options_(options),
      filter_(std::move(filter)),
      trigger_(std::move(trigger)),
      solver_(filter_->AtSolve(std::move(solver))) {}

InitEvent AnchorInitializer::SolveNow(double t_s) {
  InitEvent event;
  event.anchor_id = anchor_id_;
  event.t_s = t_s;
  event.n_used = static_cast<int>(range_m_.size());
  event.pdop_estimate = pdop_.Value();
  event.solve = solver_->Solve(p_world_tag_, range_m_);
  return event;
}

FeedResult AnchorInitializer::Feed(const RangeSample& sample) {
  FeedResult out;
  // A non-positive range carries no geometry (and would break the 1/d_k rows of Eq. (4)).
  out.accepted = sample.range_m > 0.0 && std::isfinite(sample.range_m) && filter_->Accept(sample);  // Sec. III-B
  if (out.accepted) {
    pdop_.Add(sample.p_world_tag, sample.range_m);  // Eq. (4), O(1)
    if (!initialized_) {
      if (range_m_.empty()) t_first_s_ = sample.t_s;
      p_world_tag_.push_back(sample.p_world_tag);
      range_m_.push_back(sample.range_m);
    }
  }
  out.n_accepted = pdop_.count();
  out.pdop = pdop_.Value();
  if (!out.accepted || initialized_) return out;

  TriggerInput input;
  input.t_s = sample.t_s;
  input.t_first_s = t_first_s_;
  input.p_world_tag = p_world_tag_;
  input.range_m = range_m_;
  input.pdop = out.pdop;
  input.eligible = static_cast<int>(range_m_.size()) >= options_.min_samples && range_m_.size() >= next_attempt_size_;
  if (!trigger_->Fire(input) || !input.eligible) return out;

  InitEvent event = SolveNow(sample.t_s);
  if (Succeeded(event.solve.status)) {
    initialized_ = true;
    out.event = event;
  } else {
    last_failed_solve_ = event.solve;
    next_attempt_size_ = static_cast<std::size_t>(std::ceil(range_m_.size() * options_.retry_growth));
  }
  return out;
}

std::optional<InitEvent> AnchorInitializer::Finish(double t_s) {
  if (trigger_->online() || initialized_) return std::nullopt;
  InitEvent event = SolveNow(t_s);
  initialized_ = Succeeded(event.solve.status);
  return event;
}

}  // namespace anchorbench::estimator
