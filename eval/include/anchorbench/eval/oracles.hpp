#pragma once

#include <Eigen/Core>

#include "anchorbench/estimator/init_trigger.hpp"
#include "anchorbench/eval/true_geometry.hpp"
#include "anchorbench/registry/components.hpp"

namespace anchorbench::eval {

// The oracle of Sec. IV-B: the true PDOP, Eq. (3) at the true anchor, below a threshold; O(1) per
// sample. It needs the truth, so it lives here, not in the estimator.
class TruePdopTrigger : public estimator::InitTrigger {
 public:
  TruePdopTrigger(const Eigen::Vector3d& p_world_anchor, double threshold)
      : geometry_(p_world_anchor), threshold_(threshold) {}
  bool Fire(const estimator::TriggerInput& in) override {
    geometry_.Add(in.sample_p_world_tag);
    return in.eligible && geometry_.Pdop() < threshold_;
  }

 private:
  TrueGeometry geometry_;
  double threshold_;
};

// pdop_true: built from the trigger context's reference position (the truth), refused without it.
void RegisterOracleTriggers(registry::TriggerRegistry& registry);

// The built-in parts and the oracles: what the anchorbench command offers.
registry::Components MakeComponentsWithOracles();

}  // namespace anchorbench::eval
