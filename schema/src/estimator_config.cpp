#include "anchorbench/schema/estimator_config.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace anchorbench::schema {

bool TriggerConfig::IsValid(std::string* why) const {
  auto fail = [why](const char* message) {
    if (why) *why = message;
    return false;
  };
  // A DOP threshold of 1e6 already fires on any defined geometry; durations up to 1e7 s.
  auto dop = [](double v) { return v > 0.0 && v <= 1e6; };
  if (!dop(pdop_threshold)) return fail("pdop_threshold must be in (0, 1e6]");
  if (sample_count < 1 || sample_count > 1000000000) return fail("sample_count must be in [1, 1e9]");
  if (!(timeout_s >= 0.0 && timeout_s <= 1e7)) return fail("timeout_s must be in [0, 1e7]");
  if (evaluate_every < 1 || evaluate_every > 1000000) return fail("evaluate_every must be in [1, 1e6]");
  if (!(evaluate_growth >= 1.0 && evaluate_growth <= 10.0)) return fail("evaluate_growth must be in [1, 10]");
  if (!dop(bias_aware_threshold)) return fail("bias_aware_threshold must be in (0, 1e6]");
  if (!dop(confidence_threshold)) return fail("confidence_threshold must be in (0, 1e6]");
  if (!(confidence_sigmas >= 0.0) || !(confidence_sigmas <= 10.0)) return fail("confidence_sigmas must be in [0, 10]");
  if (!dop(horizontal_threshold)) return fail("horizontal_threshold must be in (0, 1e6]");
  return true;
}

bool HeightPriorConfig::IsValid(std::string* why) const {
  // Checked whether or not it is enabled: a value a config holds is always within its range.
  for (const auto& [key, value] : {std::pair{"z_m", z_m}, std::pair{"offset_m", offset_m}}) {
    if (!(std::abs(value) <= 1e4)) {
      if (why) *why = std::string(key) + " must be in [-1e4, 1e4]";
      return false;
    }
  }
  return estimator::HeightPrior{z_m + offset_m, sigma_m}.IsValid(why);
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
