#include "anchorbench/eval/oracles.hpp"

#include <stdexcept>

namespace anchorbench::eval {

void RegisterOracleTriggers(registry::TriggerRegistry& registry) {
  registry.Register("pdop_true", "oracle: true PDOP (at the true anchor) < trigger.pdop_threshold; needs the truth",
                    [](const std::string&, const registry::TriggerContext& c) {
                      if (!c.p_world_anchor_reference) {
                        throw std::invalid_argument(
                            "needs the true anchor position (simulation, or anchors.csv in replay)");
                      }
                      return std::make_unique<TruePdopTrigger>(*c.p_world_anchor_reference, c.options.pdop_threshold);
                    });
}

registry::Components MakeComponentsWithOracles() {
  registry::Components components;
  registry::RegisterBuiltins(components);
  RegisterOracleTriggers(components.triggers);
  return components;
}

}  // namespace anchorbench::eval
