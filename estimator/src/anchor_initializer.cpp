#include "anchorbench/estimator/anchor_initializer.hpp"

#include <cmath>

namespace anchorbench::estimator {

bool InitializerOptions::IsValid(std::string* why) const {
  if (!(pdop_threshold > 0.0) || std::isnan(pdop_threshold)) {
    if (why) *why = "pdop_threshold must be > 0";
    return false;
  }
  if (min_samples < 6) {
    if (why) *why = "min_samples must be >= 6 (4 unknowns, one pivot, one redundant row)";
    return false;
  }
  if (!(retry_growth > 1.0) || !std::isfinite(retry_growth)) {
    if (why) *why = "retry_growth must be > 1";
    return false;
  }
  return filter.IsValid(why) && solver.IsValid(why);
}

AnchorInitializer::AnchorInitializer(int anchor_id, const InitializerOptions& options)
    : AnchorInitializer(anchor_id, options, std::make_shared<AnchorSolver>(options.solver)) {}

AnchorInitializer::AnchorInitializer(int anchor_id, const InitializerOptions& options,
                                     std::shared_ptr<const Solver> solver)
    : anchor_id_(anchor_id), options_(options), filter_(options.filter), solver_(std::move(solver)) {}

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
  out.accepted = sample.range_m > 0.0 && std::isfinite(sample.range_m) &&
                 filter_.Accept(sample.tag_id, sample.p_world_tag, sample.range_m);  // Sec. III-B
  if (out.accepted) {
    pdop_.Add(sample.p_world_tag, sample.range_m);  // Eq. (4), O(1)
    if (!initialized_) {
      p_world_tag_.push_back(sample.p_world_tag);
      range_m_.push_back(sample.range_m);
    }
  }
  out.n_accepted = pdop_.count();
  out.pdop = pdop_.Value();

  const bool gated = options_.strategy == InitStrategy::kPdopGated;
  if (gated && out.accepted && !initialized_ && static_cast<int>(range_m_.size()) >= options_.min_samples &&
      range_m_.size() >= next_attempt_size_ && out.pdop < options_.pdop_threshold) {
    InitEvent event = SolveNow(sample.t_s);
    if (Succeeded(event.solve.status)) {
      initialized_ = true;
      out.event = event;
    } else {
      last_failed_solve_ = event.solve;
      next_attempt_size_ = static_cast<std::size_t>(std::ceil(range_m_.size() * options_.retry_growth));
    }
  }
  return out;
}

std::optional<InitEvent> AnchorInitializer::Finish(double t_s) {
  if (options_.strategy != InitStrategy::kFixedWindow || initialized_) return std::nullopt;
  InitEvent event = SolveNow(t_s);
  initialized_ = Succeeded(event.solve.status);
  return event;
}

}  // namespace anchorbench::estimator
