#include "anchorbench/estimator/consistency_filter.hpp"

#include <cmath>

namespace anchorbench::estimator {

bool ConsistencyFilterOptions::IsValid(std::string* why) const {
  if (!(tau_m >= 0.0) || !std::isfinite(tau_m)) {
    if (why) *why = "tau_m must be >= 0";
    return false;
  }
  if (reseed_after_rejections < 0 || reseed_after_rejections > 1000000) {
    if (why) *why = "reseed_after_rejections must be in [0, 1000000]";
    return false;
  }
  return true;
}

bool ConsistencyFilter::Accept(int tag_id, const Eigen::Vector3d& p_world_tag, double range_m) {
  for (Reference& ref : references_) {
    if (ref.tag_id != tag_id) continue;
    const double delta_range_m = std::abs(range_m - ref.range_m);
    const double delta_position_m = (p_world_tag - ref.p_world_tag).norm();
    const bool consistent = delta_range_m <= delta_position_m + options_.tau_m;  // Sec. III-B
    const bool reseed = !consistent && options_.reseed_after_rejections > 0 &&
                        ref.consecutive_rejections + 1 >= options_.reseed_after_rejections;
    if (consistent || reseed) {
      ref = {tag_id, p_world_tag, range_m, 0};
      return true;
    }
    ++ref.consecutive_rejections;
    return false;
  }
  references_.push_back({tag_id, p_world_tag, range_m, 0});
  return true;
}

}  // namespace anchorbench::estimator
