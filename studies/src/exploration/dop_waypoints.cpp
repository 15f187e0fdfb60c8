#include "dop_waypoints.hpp"

#include <algorithm>
#include <limits>

#include "anchorbench/estimator/pdop.hpp"

namespace anchorbench::studies {
namespace {


// The summed PDOP with `samples` more from `p`; an anchor still singular counts a large constant,
// so that a waypoint that makes it observable is worth more than any other improvement.
double CostWith(const std::vector<PlannedAnchor>& anchors, const Eigen::Vector3d& p, double samples) {
  constexpr double kSingularPdop = 1e6;
  double cost = 0.0;
  for (PlannedAnchor a : anchors) {
    a.Add(p, samples);
    cost += std::min(kSingularPdop, estimator::BiasAwareDopFromSums(a.sum_outer, a.sum_rows, a.samples));
  }
  return cost;
}

}  // namespace

void PlannedAnchor::Add(const Eigen::Vector3d& p_world_tag, double count) {
  const Eigen::Vector3d diff = p_world_tag - p_world_anchor;
  const double distance_m = diff.norm();
  if (!(distance_m > 0.0)) return;  // at the anchor: no direction
  const Eigen::Vector3d u = diff / distance_m;
  sum_outer.noalias() += count * u * u.transpose();
  sum_rows += count * u;
  samples += count;
}

PlannedAnchor PlannedAt(const Eigen::Vector3d& p_world_anchor, std::span<const Eigen::Vector3d> p_world_tag) {
  PlannedAnchor planned;
  planned.p_world_anchor = p_world_anchor;
  for (const Eigen::Vector3d& p : p_world_tag) planned.Add(p, 1.0);
  return planned;
}

std::vector<Eigen::Vector3d> PlanDopWaypoints(std::vector<PlannedAnchor> anchors,
                                              std::span<const Eigen::Vector3d> p_world_candidate, int count,
                                              double samples_each, const Eigen::Vector3d& p_world_start) {
  std::vector<Eigen::Vector3d> chosen;
  std::vector<bool> taken(p_world_candidate.size(), false);
  for (int w = 0; w < count && !anchors.empty(); ++w) {
    std::size_t best = p_world_candidate.size();
    double best_cost = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < p_world_candidate.size(); ++c) {
      if (taken[c]) continue;
      const double cost = CostWith(anchors, p_world_candidate[c], samples_each);
      if (cost < best_cost) {  // ties: the earlier candidate
        best_cost = cost;
        best = c;
      }
    }
    if (best == p_world_candidate.size()) break;
    taken[best] = true;
    chosen.push_back(p_world_candidate[best]);
    for (PlannedAnchor& a : anchors) a.Add(p_world_candidate[best], samples_each);
  }
  // Nearest first from the start, then from each waypoint.
  std::vector<Eigen::Vector3d> route;
  Eigen::Vector3d at = p_world_start;
  while (!chosen.empty()) {
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < chosen.size(); ++i) {
      if ((chosen[i] - at).norm() < (chosen[nearest] - at).norm()) nearest = i;
    }
    at = chosen[nearest];
    route.push_back(at);
    chosen.erase(chosen.begin() + static_cast<std::ptrdiff_t>(nearest));
  }
  return route;
}

}  // namespace anchorbench::studies
