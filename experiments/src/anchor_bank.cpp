#include "anchorbench/experiments/anchor_bank.hpp"

#include <stdexcept>

#include "anchorbench/estimator/pdop.hpp"

namespace anchorbench::experiments {

using estimator::InitStrategy;

std::string_view MethodName(InitStrategy strategy) {
  return strategy == InitStrategy::kPdopGated ? "gated" : "fixed";
}

const estimator::SolverRegistry& BuiltinSolvers() {
  static const estimator::SolverRegistry registry = [] {
    estimator::SolverRegistry r;
    estimator::RegisterBuiltinSolvers(r);
    return r;
  }();
  return registry;
}

AnchorBank::AnchorBank(const estimator::InitializerOptions& options, const estimator::SolverRegistry* registry)
    : gated_options_(options), fixed_options_(options) {
  gated_options_.strategy = InitStrategy::kPdopGated;
  fixed_options_.strategy = InitStrategy::kFixedWindow;
  std::string why;
  solver_ = (registry ? *registry : BuiltinSolvers()).Create(options.solver_name, options.solver, 0, &why);
  if (!solver_) throw std::invalid_argument(why);  // configs are validated before; this is a programming error
}

AnchorBank::Anchor& AnchorBank::Find(int anchor_id) {
  auto found = anchors_.find(anchor_id);
  if (found == anchors_.end()) {
    found = anchors_
                .emplace(anchor_id, Anchor{estimator::AnchorInitializer(anchor_id, gated_options_, solver_),
                                           estimator::AnchorInitializer(anchor_id, fixed_options_, solver_),
                                           std::nullopt})
                .first;
  }
  return found->second;
}

void AnchorBank::AddAnchor(int anchor_id) { Find(anchor_id); }

estimator::FeedResult AnchorBank::Feed(const estimator::RangeSample& sample) {
  Anchor& anchor = Find(sample.anchor_id);
  anchor.fixed.Feed(sample);
  estimator::FeedResult gated = anchor.gated.Feed(sample);
  if (gated.event) anchor.gated_event = gated.event;
  return gated;
}

AttemptOutcome AnchorBank::Outcome(int anchor_id, const estimator::AnchorInitializer& initializer,
                                   const std::optional<estimator::InitEvent>& event, const AnchorTruth* truth) const {
  AttemptOutcome out;
  out.anchor_id = anchor_id;
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
  if (truth) {
    // The initializer's buffer is exactly the data of the solve (gated stops buffering at init).
    out.pdop_true = estimator::TruePdop(initializer.p_world_tag(), truth->p_world_anchor);
    out.bias_aware_dop = estimator::BiasAwareDop(initializer.p_world_tag(), truth->p_world_anchor);
    if (out.initialized) out.error_m = (out.solve->p_world_anchor - truth->p_world_anchor).norm();
  }
  return out;
}

std::vector<AttemptOutcome> AnchorBank::Finish(double t_end_s, const std::map<int, AnchorTruth>* truth) {
  std::vector<AttemptOutcome> outcomes;
  for (auto& [anchor_id, anchor] : anchors_) {
    const std::optional<estimator::InitEvent> fixed_event = anchor.fixed.Finish(t_end_s);
    const AnchorTruth* anchor_truth = nullptr;
    if (truth) {
      const auto found = truth->find(anchor_id);
      if (found != truth->end()) anchor_truth = &found->second;
    }
    AttemptOutcome gated = Outcome(anchor_id, anchor.gated, anchor.gated_event, anchor_truth);
    gated.method = InitStrategy::kPdopGated;
    AttemptOutcome fixed = Outcome(anchor_id, anchor.fixed, fixed_event, anchor_truth);
    fixed.method = InitStrategy::kFixedWindow;
    outcomes.push_back(std::move(gated));
    outcomes.push_back(std::move(fixed));
  }
  return outcomes;
}

}  // namespace anchorbench::experiments
