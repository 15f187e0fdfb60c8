#include "anchorbench/schema/pdop_study.hpp"

#include <algorithm>

namespace anchorbench::schema {

void UnderestimateStats::Add(const UnderestimateStats& other) {
  samples += other.samples;
  below += other.below;
  ideal_below += other.ideal_below;
  ideal_samples_precondition += other.ideal_samples_precondition;
  ideal_below_precondition += other.ideal_below_precondition;
  worst_ratio = std::min(worst_ratio, other.worst_ratio);
  ratios_below.insert(ratios_below.end(), other.ratios_below.begin(), other.ratios_below.end());
}

bool PdopStudyConfig::IsValid(std::string* why) const {
  if (every < 1 || every > 1000000) {
    if (why) *why = "every must be in [1, 1000000]";
    return false;
  }
  // At most 12,000 bins over the first 120 s.
  if (!(bin_s >= 0.01 && bin_s <= 120.0)) {
    if (why) *why = "bin_s must be in [0.01, 120] seconds";
    return false;
  }
  return true;
}

const char* PdopMethodName(PdopMethod method) {
  switch (method) {
    case PdopMethod::kClosestPoint: return "closest_point";
    case PdopMethod::kLs: return "ls";
    case PdopMethod::kNls: return "nls";
    case PdopMethod::kTrue: return "true";
  }
  return "unknown";
}

}  // namespace anchorbench::schema
