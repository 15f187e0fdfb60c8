#include "anchorbench/experiments/anchor_bank.hpp"

#include <chrono>
#include <stdexcept>

#include "anchorbench/estimator/pdop.hpp"
#include "anchorbench/experiments/input_error.hpp"
#include "anchorbench/sim/random_stream.hpp"

namespace anchorbench::experiments {

const estimator::Components& BuiltinComponents() {
  static const estimator::Components components = estimator::MakeBuiltinComponents();
  return components;
}

AnchorBank::AnchorBank(const estimator::InitializerOptions& options, std::uint64_t seed, std::uint64_t realization,
                       const std::map<int, AnchorTruth>* truth, const estimator::Components* components)
    : options_(options),
      seed_(seed),
      realization_(realization),
      truth_(truth),
      components_(components ? components : &BuiltinComponents()) {}

namespace {

const AnchorTruth* TruthOf(const std::map<int, AnchorTruth>* truth, int anchor_id) {
  if (!truth) return nullptr;
  const auto found = truth->find(anchor_id);
  return found == truth->end() ? nullptr : &found->second;
}

}  // namespace

AnchorBank::Anchor& AnchorBank::Find(int anchor_id) {
  if (const auto found = anchors_.find(anchor_id); found != anchors_.end()) return found->second;
  Anchor anchor;
  anchor.id = anchor_id;
  const std::uint64_t anchor_seed =
      sim::RandomStream(seed_, realization_, sim::StreamId::kSolver, static_cast<std::uint32_t>(anchor_id)).NextU64();
  const AnchorTruth* truth = TruthOf(truth_, anchor_id);
  const std::optional<Eigen::Vector3d> p_true = truth ? std::optional(truth->p_world_anchor) : std::nullopt;
  for (const std::string& trigger : options_.triggers) {
    try {
      anchor.by_trigger.push_back(estimator::MakeInitializer(*components_, anchor_id, options_, trigger, anchor_seed, p_true));
    } catch (const std::invalid_argument& e) {
      throw InputError("anchor " + std::to_string(anchor_id) + ": " + e.what());
    }
  }
  anchor.events.resize(options_.triggers.size());
  return anchors_.emplace(anchor_id, std::move(anchor)).first->second;
}

void AnchorBank::AddAnchor(int anchor_id) { Find(anchor_id); }

AttemptOutcome AnchorBank::Outcome(const Anchor& anchor, std::size_t trigger) const {
  const estimator::AnchorInitializer& initializer = anchor.by_trigger[trigger];
  const std::optional<estimator::InitEvent>& event = anchor.events[trigger];
  AttemptOutcome out;
  out.anchor_id = anchor.id;
  out.method = options_.triggers[trigger];
  out.initialized = initializer.initialized();
  out.n_used = static_cast<int>(initializer.range_m().size());
  out.pdop_estimate = initializer.pdop().Value();
  if (event) {
    out.t_init_s = event->t_s;
    out.n_used = event->n_used;
    out.pdop_estimate = event->pdop_estimate;
    out.solve = event->solve;
  } else if (initializer.last_failed_solve()) {
    out.solve = initializer.last_failed_solve();  // triggered, but every solve failed
  }
  if (const AnchorTruth* truth = TruthOf(truth_, anchor.id)) {
    // The initializer's buffer is exactly the data of the solve (online triggers stop buffering at init).
    out.pdop_true = estimator::TruePdop(initializer.p_world_tag(), truth->p_world_anchor);
    out.bias_aware_dop = estimator::BiasAwareDop(initializer.p_world_tag(), truth->p_world_anchor);
    if (out.initialized) out.error_m = (out.solve->p_world_anchor - truth->p_world_anchor).norm();
  }
  return out;
}

std::vector<AttemptOutcome> AnchorBank::Run(std::span<const estimator::RangeSample> samples, double t_end_s,
                                            const Trace& trace) {
  std::vector<Anchor*> anchor_of_sample(samples.size());  // map nodes stay put
  for (std::size_t i = 0; i < samples.size(); ++i) anchor_of_sample[i] = &Find(samples[i].anchor_id);

  std::vector<double> compute_s(options_.triggers.size(), 0.0);
  for (std::size_t t = 0; t < options_.triggers.size(); ++t) {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < samples.size(); ++i) {
      Anchor& anchor = *anchor_of_sample[i];
      estimator::FeedResult fed = anchor.by_trigger[t].Feed(samples[i]);
      if (fed.event) anchor.events[t] = fed.event;
      if (t == 0 && trace) trace(i, fed);
    }
    for (auto& [id, anchor] : anchors_) {
      if (std::optional<estimator::InitEvent> event = anchor.by_trigger[t].Finish(t_end_s)) anchor.events[t] = event;
    }
    compute_s[t] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  std::vector<AttemptOutcome> outcomes;
  for (const auto& [id, anchor] : anchors_) {
    for (std::size_t t = 0; t < options_.triggers.size(); ++t) {
      outcomes.push_back(Outcome(anchor, t));
      outcomes.back().compute_s = compute_s[t] / static_cast<double>(anchors_.size());
    }
  }
  return outcomes;
}

}  // namespace anchorbench::experiments
