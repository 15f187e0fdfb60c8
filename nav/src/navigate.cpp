#include "anchorbench/nav/navigate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace anchorbench::nav {

bool NavigationOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* message) {
    if (why) *why = message;
    return false;
  };
  if (!drift.IsValid(why)) return false;
  if (!(sigma_start_m >= 0.0 && std::isfinite(sigma_start_m))) return fail("sigma_start_m must be >= 0");
  if (!(sigma_range_m > 0.0 && std::isfinite(sigma_range_m))) return fail("sigma_range_m must be > 0");
  if (!(gate_chi2 > 0.0)) return fail("gate_chi2 must be > 0");
  if (fix_anchors < 1) return fail("fix_anchors must be >= 1");
  if (kth_anchor < 1) return fail("kth_anchor must be >= 1");
  if (!(error_bin_s > 0.0 && std::isfinite(error_bin_s))) return fail("error_bin_s must be > 0");
  return true;
}

NavigationOutcome Navigate(std::span<const double> t_s, std::span<const Eigen::Vector3d> p_world_tag,
                           std::span<const OdometryStep> odometry, const Eigen::Vector3d& p_start,
                           std::span<const RangeAt> ranges, std::vector<UsableAnchor> anchors,
                           const NavigationOptions& options) {
  if (t_s.empty() || p_world_tag.size() != t_s.size() || odometry.size() + 1 != t_s.size()) {
    throw std::invalid_argument("navigate: a trajectory of N epochs needs N positions and N - 1 odometry steps");
  }
  std::sort(anchors.begin(), anchors.end(), [](const UsableAnchor& a, const UsableAnchor& b) {
    return a.t_init_s != b.t_init_s ? a.t_init_s < b.t_init_s : a.id < b.id;
  });
  NavigationOutcome out;
  if (static_cast<int>(anchors.size()) >= 1) out.t_first_anchor_s = std::max(0.0, anchors.front().t_init_s - t_s.front());
  if (static_cast<int>(anchors.size()) >= options.kth_anchor) {
    out.t_kth_anchor_s = std::max(0.0, anchors[static_cast<std::size_t>(options.kth_anchor - 1)].t_init_s - t_s.front());
  }
  NavigationFilter filter(p_start, options.sigma_start_m, options.drift);
  const std::size_t bins = static_cast<std::size_t>((t_s.back() - t_s.front()) / options.error_bin_s) + 1;
  out.error_by_bin_m.assign(bins, 0.0);
  std::vector<int> epochs_in_bin(bins, 0);
  std::size_t next_anchor = 0, next_range = 0;
  int in_use = 0, epochs_with_fix = 0;
  double squared_sum = 0.0;
  for (std::size_t k = 0; k < t_s.size(); ++k) {
    if (k > 0) filter.Predict(odometry[k - 1]);
    for (; next_anchor < anchors.size() && anchors[next_anchor].t_init_s <= t_s[k]; ++next_anchor, ++in_use) {
      const UsableAnchor& a = anchors[next_anchor];
      filter.AddAnchor(a.id, a.p_world_anchor, a.bias_m, a.covariance, a.horizontal_only);
    }
    for (; next_range < ranges.size() && ranges[next_range].epoch <= k; ++next_range) {
      const RangeAt& r = ranges[next_range];
      if (r.epoch < k || !filter.HasAnchor(r.anchor_id)) continue;
      if (filter.UpdateRange(r.anchor_id, r.range_m, options.sigma_range_m, options.gate_chi2)) {
        ++out.ranges_used;
      } else {
        ++out.ranges_gated;
      }
    }
    const double error = (filter.position() - p_world_tag[k]).norm();
    squared_sum += error * error;
    const std::size_t bin = std::min(bins - 1, static_cast<std::size_t>((t_s[k] - t_s.front()) / options.error_bin_s));
    out.error_by_bin_m[bin] += error;
    ++epochs_in_bin[bin];
    epochs_with_fix += in_use >= options.fix_anchors;
    out.final_error_m = error;
  }
  for (std::size_t b = 0; b < bins; ++b) {
    out.error_by_bin_m[b] = epochs_in_bin[b] > 0 ? out.error_by_bin_m[b] / epochs_in_bin[b]
                                                 : std::numeric_limits<double>::quiet_NaN();
  }
  out.rmse_m = std::sqrt(squared_sum / static_cast<double>(t_s.size()));
  out.fix_share = static_cast<double>(epochs_with_fix) / static_cast<double>(t_s.size());
  return out;
}

}  // namespace anchorbench::nav
