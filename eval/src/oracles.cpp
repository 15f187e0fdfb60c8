#include "anchorbench/eval/oracles.hpp"

#include <stdexcept>

namespace anchorbench::eval {

namespace {

const Eigen::Vector3d& Truth(const registry::TriggerContext& c) {
  if (!c.p_world_anchor_reference) {
    throw std::invalid_argument("needs the true anchor position (simulation, or anchors.csv in replay)");
  }
  return *c.p_world_anchor_reference;
}

}  // namespace

void RegisterOracleTriggers(registry::TriggerRegistry& registry) {
  registry.Register("pdop_true", "oracle: true PDOP (at the true anchor) < trigger.pdop_threshold; needs the truth",
                    [](const std::string&, const registry::TriggerContext& c) {
                      return std::make_unique<TruePdopTrigger>(Truth(c), c.options.pdop_threshold);
                    });
  registry.Register("dop4_true",
                    "oracle: true bias-aware DOP < trigger.bias_aware_threshold; needs the truth",
                    [](const std::string&, const registry::TriggerContext& c) {
                      return std::make_unique<TruePdopTrigger>(Truth(c), c.options.bias_aware_threshold, true);
                    });
}

registry::Components MakeComponentsWithOracles() {
  registry::Components components;
  registry::RegisterBuiltins(components);
  RegisterOracleTriggers(components.triggers);
  return components;
}

}  // namespace anchorbench::eval
