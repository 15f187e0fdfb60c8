#include "anchorbench/schema/estimator_config.hpp"

#include <cmath>
#include <stdexcept>

namespace anchorbench::schema {

bool TriggerConfig::IsValid(std::string* why) const {
  auto fail = [why](const char* message) {
    if (why) *why = message;
    return false;
  };
  if (!(pdop_threshold > 0.0)) return fail("pdop_threshold must be > 0");
  if (sample_count < 1) return fail("sample_count must be >= 1");
  if (!(timeout_s >= 0.0) || !std::isfinite(timeout_s)) return fail("timeout_s must be >= 0");
  if (evaluate_every < 1) return fail("evaluate_every must be >= 1");
  if (!(evaluate_growth >= 1.0 && evaluate_growth <= 10.0)) return fail("evaluate_growth must be in [1, 10]");
  if (!(bias_aware_threshold > 0.0)) return fail("bias_aware_threshold must be > 0");
  if (!(confidence_threshold > 0.0)) return fail("confidence_threshold must be > 0");
  if (!(confidence_sigmas >= 0.0) || !(confidence_sigmas <= 10.0)) return fail("confidence_sigmas must be in [0, 10]");
  if (!(horizontal_threshold > 0.0)) return fail("horizontal_threshold must be > 0");
  return true;
}

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
