#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/estimator/front_end.hpp"
#include "anchorbench/estimator/guidance.hpp"

namespace anchorbench::estimator {

// What to ask of guidance (guidance.hpp) for every anchor a front end tracks.
struct GuideRequest {
  // Where the robot could range from next; empty: CandidateGrid around the anchor's last tag
  // position, reach_m to each side in `steps` steps.
  std::vector<Eigen::Vector3d> p_world_candidate;
  double reach_m = 2.0;
  int steps = 2;
  double samples = 50.0;     // more ranges per candidate the ranking assumes
  std::size_t best = 5;      // candidates kept per anchor
  double range_rate_hz = 10.0;  // the link's ranging rate at a candidate: samples -> seconds
};

// One waiting anchor's guidance, from one chain whose trigger judges a region (certified).
struct AnchorGuidance {
  int anchor_id = 0;
  std::size_t chain = 0;
  // The test that holds the anchor back now (Judgement::blocked_by). The forecast is the region's:
  // where the mirror, an alternative or the stability holds it, the samples to certify are those
  // of the region's test alone (docs/guidance.md).
  std::string_view blocked_by;
  double region_m = 0.0;    // the region's radius now (the forecast's, from the estimate)
  double accuracy_m = 0.0;  // D
  std::vector<CandidateForecast> best;  // best first
  double seconds_to_certify = 0.0;  // the fewest samples to certify among `best`, over range_rate_hz
                                    // (+inf: none of them brings the region within D)
};

// Guidance for every chain of every anchor not yet initialized whose trigger has judged an
// estimate; anchors in ascending order. O(N) per such chain for its forecast, O(1) per candidate.
std::vector<AnchorGuidance> Guide(const FrontEnd& front_end, const GuideRequest& request);

}  // namespace anchorbench::estimator
