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
