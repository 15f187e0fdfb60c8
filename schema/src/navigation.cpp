#include "anchorbench/schema/navigation.hpp"

#include <cmath>

namespace anchorbench::schema {

bool NavigationConfig::IsValid(std::string* why) const {
  auto fail = [why](const char* message) {
    if (why) *why = message;
    return false;
  };
  auto non_negative = [](double v) { return v >= 0.0 && std::isfinite(v); };
  if (!non_negative(sigma_bias_mps_per_sqrt_s)) return fail("sigma_bias_mps_per_sqrt_s must be >= 0");
  if (!non_negative(sigma_heading_rad_per_sqrt_s)) return fail("sigma_heading_rad_per_sqrt_s must be >= 0");
  if (!non_negative(sigma_step_m_per_sqrt_s)) return fail("sigma_step_m_per_sqrt_s must be >= 0");
  if (!non_negative(sigma_start_m)) return fail("sigma_start_m must be >= 0");
  if (!non_negative(sigma_range_m)) return fail("sigma_range_m must be >= 0 (0: the row's ranging.sigma_range_m)");
  if (!(gate_chi2 > 0.0)) return fail("gate_chi2 must be > 0");
  if (fix_anchors < 1) return fail("fix_anchors must be >= 1");
  if (kth_anchor < 1) return fail("kth_anchor must be >= 1");
  if (!(error_bin_s > 0.0 && std::isfinite(error_bin_s))) return fail("error_bin_s must be > 0");
  return true;
}

}  // namespace anchorbench::schema
