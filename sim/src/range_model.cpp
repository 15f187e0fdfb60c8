#include "anchorbench/sim/range_model.hpp"

#include <cmath>
#include <string>

namespace anchorbench::sim {

bool RangeModelOptions::IsValid(std::string* why) const {
  auto fail = [why](std::string m) {
    if (why) *why = std::move(m);
    return false;
  };
  // Radio errors up to 100 m, ranges up to 1000 km: far beyond UWB, and never a non-finite range.
  auto within = [](double v, double limit) { return v >= 0.0 && v <= limit; };
  if (!within(sigma_range_m, 100.0)) return fail("sigma_range_m must be in [0, 100]");
  if (!(std::abs(bias_a_m) <= 100.0)) return fail("bias_a_m must be in [-100, 100]");
  if (!(std::abs(bias_b_m) <= 100.0)) return fail("bias_b_m must be in [-100, 100]");
  if (bias_distribution == BiasDistribution::kUniform && !(bias_a_m <= bias_b_m))
    return fail("bias_b_m must be >= bias_a_m for a uniform bias");
  if (bias_distribution == BiasDistribution::kNormal && !(bias_b_m >= 0.0))
    return fail("bias_b_m (the normal bias's sigma) must be >= 0");
  if (!(outlier_probability >= 0.0 && outlier_probability <= 1.0)) return fail("outlier_probability must be in [0, 1]");
  if (!(outlier_burst_length >= 1.0 && outlier_burst_length <= 1e6)) return fail("outlier_burst_length must be in [1, 1e6]");
  // Episodes start at rate p/(L (1 - p)) per clean range (scenario.cpp), which must be a
  // probability: bursts of mean length L cannot make more than L/(L+1) of the ranges outliers.
  const double reachable = outlier_burst_length / (outlier_burst_length + 1.0);
  if (outlier_probability > reachable) {
    return fail("outlier_probability must be <= L/(L+1) = " + std::to_string(reachable) +
                " for outlier_burst_length L = " + std::to_string(outlier_burst_length) +
                " (an episode always ends on a clean range)");
  }
  if (!within(outlier_min_m, 1e6)) return fail("outlier_min_m must be in [0, 1e6]");
  if (!(outlier_max_m >= outlier_min_m && outlier_max_m <= 1e6)) return fail("outlier_max_m must be in [outlier_min_m, 1e6]");
  if (!(max_range_m > 0.0 && max_range_m <= 1e6)) return fail("max_range_m must be in (0, 1e6]");
  if (!(dropout_probability >= 0.0 && dropout_probability < 1.0)) return fail("dropout_probability must be in [0, 1)");
  if (!within(sigma_position_m, 100.0)) return fail("sigma_position_m must be in [0, 100]");
  if (!(antenna_bias_m >= 0.0 && antenna_bias_m <= 10.0)) return fail("antenna_bias_m must be in [0, 10]");
  if (!(tag_antenna_bias_m >= 0.0 && tag_antenna_bias_m <= 10.0)) return fail("tag_antenna_bias_m must be in [0, 10]");
  if (!(link_offset_m >= 0.0 && link_offset_m <= 100.0)) return fail("link_offset_m must be in [0, 100]");
  if (!(range_scale_sigma >= 0.0 && range_scale_sigma <= 0.5)) return fail("range_scale_sigma must be in [0, 0.5]");
  return true;
}

}  // namespace anchorbench::sim
