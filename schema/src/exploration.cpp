#include "anchorbench/schema/exploration.hpp"

#include <algorithm>

namespace anchorbench::schema {

bool ExplorationConfig::IsValid(std::string* why) const {
  auto fail = [why](const char* message) {
    if (why) *why = message;
    return false;
  };
  auto known = [](const std::string& p) {
    return p == kPatternPolicy || p == kGuidedPolicy || p == kOraclePolicy || p == kDopWaypointsPolicy;
  };
  if (policies.empty() || !std::all_of(policies.begin(), policies.end(), known)) {
    return fail("policies must list one or more of: pattern, guided, oracle, dop_waypoints");
  }
  if (trigger.empty()) return fail("trigger must name a trigger that judges a region (certified)");
  // Bounds that keep a run's epochs and a decision's candidates finite and few.
  if (!(max_duration_s > 0.0 && max_duration_s <= 1e5)) return fail("max_duration_s must be in (0, 1e5]");
  if (!(decision_period_s >= 0.1 && decision_period_s <= 1e5)) return fail("decision_period_s must be in [0.1, 1e5]");
  if (!(reach_m > 0.0 && reach_m <= 1000.0)) return fail("reach_m must be in (0, 1000]");
  if (grid_steps < 1 || grid_steps > 10) return fail("grid_steps must be in [1, 10]");
  if (!(dwell_s >= 0.0 && dwell_s <= 1e4)) return fail("dwell_s must be in [0, 1e4]");
  if (detours_per_anchor < 1 || detours_per_anchor > 1000) return fail("detours_per_anchor must be in [1, 1000]");
  if (!(speed_mps > 0.0 && speed_mps <= 100.0)) return fail("speed_mps must be in (0, 100]");
  if (!(plan_after_s >= 0.0 && plan_after_s <= 1e5)) return fail("plan_after_s must be in [0, 1e5]");
  if (waypoints < 1 || waypoints > 100) return fail("waypoints must be in [1, 100]");
  if (!(clearance_m >= 0.0 && clearance_m <= 100.0)) return fail("clearance_m must be in [0, 100]");
  return true;
}

}  // namespace anchorbench::schema
