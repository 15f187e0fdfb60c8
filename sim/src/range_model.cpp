#include "anchorbench/sim/range_model.hpp"

#include <cmath>

namespace anchorbench::sim {

std::string_view ToString(BiasDistribution d) { return d == BiasDistribution::kUniform ? "uniform" : "normal"; }
std::string_view ToString(OutlierKind k) { return k == OutlierKind::kPositive ? "positive" : "symmetric"; }

bool ParseBiasDistribution(std::string_view name, BiasDistribution* d) {
  if (name == "uniform") *d = BiasDistribution::kUniform;
  else if (name == "normal") *d = BiasDistribution::kNormal;
  else return false;
  return true;
}

bool ParseOutlierKind(std::string_view name, OutlierKind* k) {
  if (name == "positive") *k = OutlierKind::kPositive;
  else if (name == "symmetric") *k = OutlierKind::kSymmetric;
  else return false;
  return true;
}

bool RangeModelOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* m) {
    if (why) *why = m;
    return false;
  };
  if (!(sigma_range_m >= 0.0) || !std::isfinite(sigma_range_m)) return fail("sigma_range_m must be >= 0");
  if (!std::isfinite(bias_a_m) || !std::isfinite(bias_b_m)) return fail("bias bounds must be finite");
  if (bias_distribution == BiasDistribution::kUniform && !(bias_a_m <= bias_b_m))
    return fail("uniform bias needs bias_a_m <= bias_b_m");
  if (bias_distribution == BiasDistribution::kNormal && !(bias_b_m >= 0.0))
    return fail("normal bias needs bias_b_m (sigma) >= 0");
  if (!(outlier_probability >= 0.0 && outlier_probability <= 1.0)) return fail("outlier_probability must be in [0, 1]");
  if (!(outlier_burst_length >= 1.0) || !std::isfinite(outlier_burst_length))
    return fail("outlier_burst_length must be >= 1");
  if (!(outlier_min_m >= 0.0 && outlier_min_m <= outlier_max_m) || !std::isfinite(outlier_max_m))
    return fail("outlier magnitudes must satisfy 0 <= min <= max");
  if (!(max_range_m > 0.0)) return fail("max_range_m must be > 0");
  if (!(dropout_probability >= 0.0 && dropout_probability < 1.0)) return fail("dropout_probability must be in [0, 1)");
  if (!(sigma_position_m >= 0.0) || !std::isfinite(sigma_position_m)) return fail("sigma_position_m must be >= 0");
  return true;
}

}  // namespace anchorbench::sim
