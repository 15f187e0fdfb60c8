#include "anchorbench/schema/navigation.hpp"

#include <cmath>

namespace anchorbench::schema {

bool NavigationConfig::IsValid(std::string* why) const {
  auto fail = [why](const char* message) {
    if (why) *why = message;
    return false;
  };
  // Drifts far beyond any odometry's (a filter's squared errors stay finite), and time bins of at
  // least 10 ms (the realization's bins are bounded in studies::CheckNavigation too).
  auto within = [](double v, double limit) { return v >= 0.0 && v <= limit; };
  if (!within(sigma_bias_mps_per_sqrt_s, 10.0)) return fail("sigma_bias_mps_per_sqrt_s must be in [0, 10]");
  if (!within(sigma_heading_rad_per_sqrt_s, 1.0)) return fail("sigma_heading_rad_per_sqrt_s must be in [0, 1]");
  if (!within(sigma_step_m_per_sqrt_s, 10.0)) return fail("sigma_step_m_per_sqrt_s must be in [0, 10]");
  if (!within(sigma_start_m, 1000.0)) return fail("sigma_start_m must be in [0, 1000]");
  if (!within(sigma_range_m, 100.0)) return fail("sigma_range_m must be in [0, 100] (0: the row's ranging.sigma_range_m)");
  if (!(gate_chi2 > 0.0 && gate_chi2 <= 1e6)) return fail("gate_chi2 must be in (0, 1e6]");
  if (fix_anchors < 1 || fix_anchors > 10000) return fail("fix_anchors must be in [1, 10000]");
  if (kth_anchor < 1 || kth_anchor > 10000) return fail("kth_anchor must be in [1, 10000]");
  if (!(error_bin_s >= 0.01 && error_bin_s <= 1e6)) return fail("error_bin_s must be in [0.01, 1e6]");
  return true;
}

}  // namespace anchorbench::schema
