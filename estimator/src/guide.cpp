#include "anchorbench/estimator/guide.hpp"

#include <algorithm>
#include <limits>

namespace anchorbench::estimator {

std::vector<AnchorGuidance> Guide(const FrontEnd& front_end, const GuideRequest& request) {
  std::vector<AnchorGuidance> out;
  for (const int anchor_id : front_end.anchor_ids()) {
    const std::vector<AnchorInitializer>& chains = front_end.chains(anchor_id);
    for (std::size_t chain = 0; chain < chains.size(); ++chain) {
      const std::optional<RegionForecast> forecast = chains[chain].Forecast();
      if (!forecast || chains[chain].p_world_tag().empty()) continue;
      const std::vector<Eigen::Vector3d> grid =
          request.p_world_candidate.empty()
              ? CandidateGrid(chains[chain].p_world_tag().back(), request.reach_m, request.steps)
              : std::vector<Eigen::Vector3d>{};
      const std::span<const Eigen::Vector3d> candidates =
          request.p_world_candidate.empty() ? std::span<const Eigen::Vector3d>(grid) : request.p_world_candidate;
      AnchorGuidance guidance;
      guidance.anchor_id = anchor_id;
      guidance.chain = chain;
      if (const std::optional<Judgement> judged = chains[chain].why_not()) guidance.blocked_by = judged->blocked_by;
      guidance.region_m = forecast->region_m();
      guidance.accuracy_m = forecast->basis().accuracy_m;
      guidance.best = forecast->Rank(candidates, request.samples, request.best);
      double fewest = std::numeric_limits<double>::infinity();
      for (const CandidateForecast& c : guidance.best) fewest = std::min(fewest, c.samples_to_certify);
      guidance.seconds_to_certify = fewest / request.range_rate_hz;
      out.push_back(std::move(guidance));
    }
  }
  return out;
}

}  // namespace anchorbench::estimator
