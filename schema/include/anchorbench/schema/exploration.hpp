#pragma once
// The closed-loop exploration study's settings (the config's `exploration` section; anchorbench
// explore, docs/guidance.md): how the robot moves, when it asks guidance, and which policies run.
// Plain data; studies/exploration.hpp runs them.

#include <string>
#include <vector>

namespace anchorbench::schema {

inline constexpr const char* kPatternPolicy = "pattern";  // the row's trajectory, back and forth
inline constexpr const char* kGuidedPolicy = "guided";    // the pattern with detours guidance picks
inline constexpr const char* kOraclePolicy = "oracle";    // the same, ranked at the true anchors
inline constexpr const char* kDopWaypointsPolicy = "dop_waypoints";  // uwb_init's idea: waypoints planned once

struct ExplorationConfig {
  std::vector<std::string> policies = {kPatternPolicy, kGuidedPolicy};
  // The trigger whose initializations count (a trigger that judges a region: certified). Guidance
  // reads its certificate; the time to certify is its last anchor's.
  std::string trigger = "certified";
  double max_duration_s = 600.0;     // the run stops here if an anchor is still waiting
  double decision_period_s = 2.0;    // guided: asks guidance this often while on the pattern
  double reach_m = 3.0;              // guided: candidates within this of the body, per axis
  int grid_steps = 2;                // and this many steps to each side (a (2 steps + 1)^3 grid)
  double dwell_s = 5.0;              // guided: ranging at a candidate for this long, then back
  int detours_per_anchor = 2;        // guided: at most this many detours for one anchor
  double speed_mps = 1.0;            // the speed off the pattern (detours, waypoints)
  double plan_after_s = 60.0;        // dop_waypoints: the waypoints are planned this long into the run
  int waypoints = 8;                 // dop_waypoints: this many, dwell_s at each
  double clearance_m = 0.5;          // candidates stay this far inside the environment's box
  bool vertical = true;              // candidates may change height (a drone); false: a ground robot

  bool IsValid(std::string* why) const;
};

}  // namespace anchorbench::schema
