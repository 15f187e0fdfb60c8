#pragma once

#include <cstddef>
#include <optional>

#include <Eigen/Core>

#include "anchorbench/estimator/init_trigger.hpp"
#include "anchorbench/eval/true_geometry.hpp"
#include "anchorbench/registry/components.hpp"

namespace anchorbench::eval {

// The oracle of Sec. IV-B: the true PDOP, Eq. (3) at the true anchor, below a threshold; O(1) per
// sample. It needs the truth, so it lives here, not in the estimator.
// With `bias_aware`, the true bias-aware DOP instead (the 4-column oracle, dop4_true).
class TruePdopTrigger : public estimator::InitTrigger {
 public:
  TruePdopTrigger(const Eigen::Vector3d& p_world_anchor, double threshold, bool bias_aware = false)
      : geometry_(p_world_anchor), threshold_(threshold), bias_aware_(bias_aware) {}
  bool Fire(const estimator::TriggerInput& in) override {
    geometry_.Add(in.sample_p_world_tag);
    last_t_s_ = in.t_s;
    last_samples_ = in.range_m.size();
    return in.eligible && Value() < threshold_;
  }
  std::optional<estimator::Judgement> why_not() const override {
    if (last_samples_ == 0) return std::nullopt;
    return estimator::BlockedBy(bias_aware_ ? "dop4_true" : "pdop_true", Value(), threshold_, last_t_s_, last_samples_);
  }

 private:
  double Value() const { return bias_aware_ ? geometry_.BiasAwareDop() : geometry_.Pdop(); }
  TrueGeometry geometry_;
  double threshold_;
  bool bias_aware_;
  double last_t_s_ = estimator::Judgement::kNone;
  std::size_t last_samples_ = 0;
};

// pdop_true and dop4_true: built from the trigger context's reference position (the truth),
// refused without it.
void RegisterOracleTriggers(registry::TriggerRegistry& registry);

// The built-in parts and the oracles: what the anchorbench command offers.
registry::Components MakeComponentsWithOracles();

}  // namespace anchorbench::eval
