#pragma once
// The offline-waypoint baseline of the exploration study (studies/exploration.hpp): the idea of the
// authors' library (aau-cns/uwb_init: initialize, plan waypoints by a DOP cost, fly them, refine),
// reimplemented here, not its code. Ours: the cost is the sum over the anchors of the PDOP of
// (p_A, gamma) at each anchor's first estimate, with the samples so far and dwell x rate samples
// from each waypoint; the waypoints are chosen greedily from a grid, not by a genetic algorithm,
// and flown nearest first.

#include <span>
#include <vector>

#include <Eigen/Core>

namespace anchorbench::studies {

// An anchor's geometry at its estimate: the sums of the unit directions u to its samples' tags
// (sum u u^T, sum u, and their count), from which estimator::BiasAwareDopFromSums gives the PDOP of
// (p_A, gamma).
struct PlannedAnchor {
  Eigen::Vector3d p_world_anchor = Eigen::Vector3d::Zero();  // its estimate
  Eigen::Matrix3d sum_outer = Eigen::Matrix3d::Zero();
  Eigen::Vector3d sum_rows = Eigen::Vector3d::Zero();
  double samples = 0.0;

  // `count` samples more from a tag at `p_world_tag`.
  void Add(const Eigen::Vector3d& p_world_tag, double count);
};

// The sums at `p_world_anchor` of ranges from `p_world_tag`.
PlannedAnchor PlannedAt(const Eigen::Vector3d& p_world_anchor, std::span<const Eigen::Vector3d> p_world_tag);

// `count` distinct candidates, greedily the one that lowers the summed PDOP most with
// `samples_each` samples from it, in the order to fly them from `p_world_start` (nearest first).
std::vector<Eigen::Vector3d> PlanDopWaypoints(std::vector<PlannedAnchor> anchors,
                                              std::span<const Eigen::Vector3d> p_world_candidate, int count,
                                              double samples_each, const Eigen::Vector3d& p_world_start);

}  // namespace anchorbench::studies
