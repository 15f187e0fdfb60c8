#include "anchorbench/schema/estimator_config.hpp"

#include <cmath>
#include <stdexcept>

namespace anchorbench::schema {

bool HeightPriorConfig::IsValid(std::string* why) const {
  if (!enabled) return true;
  const estimator::HeightPrior prior{z_m + offset_m, sigma_m};
  if (!prior.IsValid(why)) return false;
  if (!std::isfinite(offset_m)) {
    if (why) *why = "height_prior.offset_m must be finite";
    return false;
  }
  return true;
}

std::optional<estimator::HeightPrior> HeightPriorConfig::For(
    int anchor_id, const std::optional<Eigen::Vector3d>& p_world_reference) const {
  if (!enabled) return std::nullopt;
  if (!from_reference) return estimator::HeightPrior{z_m + offset_m, sigma_m};
  if (!p_world_reference) {
    throw std::invalid_argument("height_prior.from_reference: anchor " + std::to_string(anchor_id) +
                                " has no reference position (replay: give its surveyed position)");
  }
  return estimator::HeightPrior{p_world_reference->z() + offset_m, sigma_m};
}

bool EstimatorConfig::IsValid(std::string* why) const {
  if (triggers.empty()) {
    if (why) *why = "triggers must name at least one trigger";
    return false;
  }
  return filter.consistency.IsValid(why) && filter.ransac.IsValid(why) && trigger.IsValid(why) &&
         initializer.IsValid(why) && solver_options.IsValid(why) && height_prior.IsValid(why) &&
         certificate.IsValid(why);
}

}  // namespace anchorbench::schema
