#include "anchorbench/estimator/anchor_initializer.hpp"

#include <cmath>

#include "anchorbench/estimator/triggers.hpp"

namespace anchorbench::estimator {

bool InitializerOptions::IsValid(std::string* why) const {
  auto fail = [why](std::string message) {
    if (why) *why = std::move(message);
    return false;
  };
  if (min_samples < kMinSamplesLs) {
    return fail("min_samples must be >= " + std::to_string(kMinSamplesLs) +
                " (4 unknowns, one pivot, one redundant row)");
  }
  // Bounded so that the retry size (an integer) cannot overflow.
  if (!(retry_growth > 1.0 && retry_growth <= 100.0)) return fail("retry_growth must be in (1, 100]");
  // At most 1e7 samples (360 MB) a chain: memory stays bounded whatever the config says.
  if (max_buffered_samples > 10000000) return fail("max_buffered_samples must be <= 1e7");
  if (max_buffered_samples / 2 < min_samples) {
    return fail("max_buffered_samples must be >= 2 min_samples (a thinned buffer keeps half)");
  }
  return height_check.IsValid(why) && covariance.IsValid(why) && tag_biases.IsValid(why);
}

AnchorInitializer::AnchorInitializer(int anchor_id, const InitializerOptions& options,
                                     std::unique_ptr<OutlierFilter> filter, std::unique_ptr<InitTrigger> trigger,
                                     std::shared_ptr<const Solver> solver)
    : anchor_id_(anchor_id),
      options_(options),
      filter_(std::move(filter)),
      trigger_(std::move(trigger)),
      solver_(filter_->AtSolve(std::move(solver))) {
  if (options_.height_check.enabled) solver_ = std::make_shared<HeightCheckedSolver>(solver_, options_.height_check);
  // The whole buffer at once: address space only until samples are written, and no sample ever
  // reallocates it (no O(N) copy inside Feed, no memory returned and touched again as it grows).
  const auto cap = static_cast<std::size_t>(options_.max_buffered_samples);
  p_world_tag_.reserve(cap);
  range_m_.reserve(cap);
  tag_id_.reserve(cap);
}

InitEvent AnchorInitializer::SolveNow(double t_s, double pdop) const {
  InitEvent event;
  event.anchor_id = anchor_id_;
  event.t_s = t_s;
  event.n_used = static_cast<int>(range_m_.size());
  event.pdop_closest_point = pdop;
  std::vector<double> fitted_m;  // the ranges less each tag's offset: what the covariance judges
  event.solve = SolveWithTagBiases(*solver_, p_world_tag_, range_m_, tag_id_, options_.tag_biases, nullptr, &fitted_m);
  trigger_->AdoptJudged(&event.solve);
  const OutlierFilter& filter = *filter_;
  CovarianceOptions covariance = options_.covariance;
  if (options_.tag_biases.estimate) covariance.link_offset_m = 0.0;  // estimated: their own term
  MakeCredible(p_world_tag_, fitted_m, tag_id_, covariance,
               [&filter](double scale_m, double slack_m) { return filter.TravelBias(scale_m, slack_m); }, &event.solve);
  return event;
}

void AnchorInitializer::Buffer(int tag_id, const Eigen::Vector3d& p_world_tag, double range_m) {
  const std::size_t cap = static_cast<std::size_t>(options_.max_buffered_samples);
  const std::size_t index = n_admitted_ - 1;  // of this sample among the admitted ones
  if (options_.at_cap == BufferPolicy::kThin) {
    if (index % keep_every_ != 0) {
      ++samples_not_buffered_;
      return;
    }
    if (range_m_.size() == cap) {  // keep the even positions: every 2 keep_every_-th sample
      for (std::size_t i = 0; 2 * i < range_m_.size(); ++i) {
        p_world_tag_[i] = p_world_tag_[2 * i];
        range_m_[i] = range_m_[2 * i];
        tag_id_[i] = tag_id_[2 * i];
      }
      samples_not_buffered_ += static_cast<long>(range_m_.size() / 2);
      p_world_tag_.resize((range_m_.size() + 1) / 2);
      range_m_.resize((range_m_.size() + 1) / 2);
      tag_id_.resize(range_m_.size());
      keep_every_ *= 2;
      if (index % keep_every_ != 0) {
        ++samples_not_buffered_;
        return;
      }
    }
  } else if (range_m_.size() == cap) {
    ++samples_not_buffered_;
    return;
  }
  p_world_tag_.push_back(p_world_tag);
  range_m_.push_back(range_m);
  tag_id_.push_back(tag_id);
}

void AnchorInitializer::Admit(const Accepted& sample) {
  if (n_admitted_ == 0) t_first_s_ = sample.t_s;
  t_last_s_ = sample.t_s;
  ++n_admitted_;
  Buffer(sample.tag_id, sample.p_world_tag, sample.range_m);
  TriggerInput input;
  input.t_s = sample.t_s;
  input.t_first_s = t_first_s_;
  input.n_admitted = n_admitted_;
  input.sample_p_world_tag = sample.p_world_tag;
  input.sample_range_m = sample.range_m;
  input.p_world_tag = p_world_tag_;
  input.range_m = range_m_;
  input.tag_id = tag_id_;
  input.pdop = sample.pdop;
  input.eligible = n_admitted_ >= static_cast<std::size_t>(options_.min_samples) && n_admitted_ >= next_attempt_size_;
  if (trigger_->Fire(input) && input.eligible) pending_ = input;
}

FeedResult AnchorInitializer::Feed(const RangeSample& sample) {
  FeedResult out;
  // A non-positive range carries no geometry (and would break the 1/d_k rows of Eq. (4)).
  out.accepted = sample.range_m > 0.0 && std::isfinite(sample.range_m) && filter_->Accept(sample);  // Sec. III-B
  if (out.accepted) pdop_.Add(sample.p_world_tag, sample.range_m);                                    // Eq. (4), O(1)
  out.n_accepted = pdop_.count();
  out.pdop = pdop_.Value();
  if (!out.accepted || initialized_) return out;

  const Accepted accepted{sample.t_s, sample.tag_id, sample.p_world_tag, sample.range_m, out.pdop};
  if (pending_) {  // a deferred solve decides whether this sample is still needed
    if (queued_.size() < static_cast<std::size_t>(options_.max_buffered_samples)) {
      queued_.push_back(accepted);
    } else {
      ++samples_dropped_while_pending_;
    }
  } else {
    Admit(accepted);
    if (pending_ && !defer_solves_) out.event = RunPendingSolve();
  }
  out.solve_pending = pending_.has_value();
  return out;
}

std::optional<InitEvent> AnchorInitializer::RunPendingSolve() {
  if (!pending_) return std::nullopt;
  return CompletePendingSolve(WorkPendingSolve());
}

PendingWork AnchorInitializer::WorkPendingSolve() {
  PendingWork work;
  if (!pending_ || !trigger_->Evaluate(*pending_)) return work;
  work.solved = true;
  work.event = SolveNow(pending_->t_s, pending_->pdop);
  return work;
}

std::optional<InitEvent> AnchorInitializer::CompletePendingSolve(const PendingWork& work) {
  if (!pending_) return std::nullopt;
  pending_.reset();
  if (work.solved && Succeeded(work.event.solve.status)) {
    initialized_ = true;
    queued_.clear();
    return work.event;
  }
  if (work.solved) {  // failed: wait for more data before the next attempt
    last_failed_solve_ = work.event;
    next_attempt_size_ =
        static_cast<std::size_t>(std::ceil(static_cast<double>(n_admitted_) * options_.retry_growth));
  }
  // Catch up on what arrived while the solve was pending (nothing, when solving inline).
  while (!queued_.empty() && !pending_) {
    Admit(queued_.front());
    queued_.pop_front();
  }
  return std::nullopt;
}

std::optional<RegionForecast> AnchorInitializer::Forecast() const {
  if (initialized_) return std::nullopt;
  const std::optional<RegionBasis> basis = trigger_->region_basis();
  if (!basis) return std::nullopt;
  return RegionForecast(*basis, p_world_tag_, tag_id_);
}

std::optional<Judgement> AnchorInitializer::why_not() const {
  if (initialized_ || n_admitted_ == 0) return std::nullopt;
  auto own = [this](std::string_view test, double limit) {
    return BlockedBy(test, static_cast<double>(n_admitted_), limit, Judgement::kNone, range_m_.size());
  };
  if (n_admitted_ < static_cast<std::size_t>(options_.min_samples)) return own("samples", options_.min_samples);
  // A solve the mirror check refused, while it still stands (the fixed window's at the end, or an
  // online trigger's until its retry): the check's own numbers say more than the retry's count.
  const bool refusal_stands = !trigger_->online() || n_admitted_ < next_attempt_size_;
  if (refusal_stands && last_failed_solve_ && last_failed_solve_->solve.mirror_refusal) {
    return MirrorJudgement(*last_failed_solve_->solve.mirror_refusal, last_failed_solve_->t_s);
  }
  if (n_admitted_ < next_attempt_size_) return own("retry", static_cast<double>(next_attempt_size_));
  return trigger_->why_not();
}

std::optional<Judgement> AnchorInitializer::TakeJudgement() {
  const std::size_t evaluations = trigger_->evaluations();
  if (evaluations == judgements_taken_) return std::nullopt;
  judgements_taken_ = evaluations;
  return trigger_->why_not();
}

std::optional<InitEvent> AnchorInitializer::Finish(double t_s) {
  while (pending_) {
    if (std::optional<InitEvent> event = RunPendingSolve()) return event;
  }
  if (trigger_->online() || initialized_) return std::nullopt;
  // At the anchor's own last sample, not the data's end: what other anchors' or tags' rows do (or
  // a range dropped at the end) never moves this anchor's time.
  InitEvent event = SolveNow(n_admitted_ > 0 ? t_last_s_ : t_s, pdop_.Value());
  initialized_ = Succeeded(event.solve.status);
  if (!initialized_) last_failed_solve_ = event;  // why_not() reads it
  return event;
}

AnchorInitializer MakePaperInitializer(int anchor_id, const PaperChainOptions& options,
                                       std::shared_ptr<const LogPartitionTable> table) {
  return AnchorInitializer(anchor_id, options.initializer, std::make_unique<ConsistencyFilter>(options.filter),
                           std::make_unique<ClosestPointPdopTrigger>(options.pdop_threshold),
                           std::make_shared<AnchorSolver>(options.solver, std::move(table)));
}

}  // namespace anchorbench::estimator
