#include "anchorbench/estimator/consistency_filter.hpp"

#include <cmath>
#include <iterator>

namespace anchorbench::estimator {

bool ConsistencyFilterOptions::IsValid(std::string* why) const {
  if (!(tau_m >= 0.0 && tau_m <= 1e4)) {
    if (why) *why = "tau_m must be in [0, 1e4]";
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

double ConsistencyFilter::TravelBias(double difference_scale_m, double slack_m) const {
  // g((tau + s) / q), linear between the measured points (consistency_filter.hpp), 0 beyond 12.
  constexpr double kRatio[] = {0.0, 0.5, 0.92, 1.52, 2.0, 2.4, 3.2, 5.0, 8.0, 12.0};
  constexpr double kBias[] = {1.25, 1.25, 1.2, 0.85, 0.43, 0.2, 0.05, 0.02, 0.015, 0.0};
  if (!(difference_scale_m > 0.0) || !std::isfinite(difference_scale_m)) return 0.0;
  const double ratio = (options_.tau_m + slack_m) / difference_scale_m;
  for (std::size_t i = 1; i < std::size(kRatio); ++i) {
    if (ratio <= kRatio[i]) {
      const double w = (ratio - kRatio[i - 1]) / (kRatio[i] - kRatio[i - 1]);
      return ((1.0 - w) * kBias[i - 1] + w * kBias[i]) * difference_scale_m;
    }
  }
  return 0.0;
}

}  // namespace anchorbench::estimator
