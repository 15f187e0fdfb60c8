#include "anchorbench/registry/estimator_config.hpp"

namespace anchorbench::registry {

bool EstimatorConfig::IsValid(std::string* why) const {
  if (triggers.empty()) {
    if (why) *why = "triggers must name at least one trigger";
    return false;
  }
  return filter.consistency.IsValid(why) && filter.ransac.IsValid(why) && trigger.IsValid(why) &&
         initializer.IsValid(why) && solver_options.IsValid(why);
}

}  // namespace anchorbench::registry
