#pragma once
// The offline-waypoint baseline of the exploration study (engine/exploration.hpp): the idea of the
// authors' library (aau-cns/uwb_init: initialize, plan waypoints by a DOP cost, fly them, refine),
// reimplemented here, not its code. Ours: the cost is the sum over the anchors of the PDOP of
// (p_A, gamma) at each anchor's first estimate, with the samples so far and dwell x rate samples
// from each waypoint; the waypoints are chosen greedily from a grid, not by a genetic algorithm,
// and flown nearest first.

#include <span>
#include <vector>

#include <Eigen/Core>

namespace anchorbench::engine {

struct PlannedAnchor {
  Eigen::Vector3d p_world_anchor;           // its estimate
  Eigen::Matrix4d information;              // of (p_A, gamma): sum of [-u, 1]^T [-u, 1] over its samples
};

// The information of (p_A, gamma) at `p_world_anchor` from ranges at `p_world_tag` (unit weights).
Eigen::Matrix4d RangeInformation(std::span<const Eigen::Vector3d> p_world_tag, const Eigen::Vector3d& p_world_anchor);

// `count` distinct candidates, greedily the one that lowers the summed PDOP most with
// `samples_each` samples from it, in the order to fly them from `p_world_start` (nearest first).
std::vector<Eigen::Vector3d> PlanDopWaypoints(std::vector<PlannedAnchor> anchors,
                                              std::span<const Eigen::Vector3d> p_world_candidate, int count,
                                              double samples_each, const Eigen::Vector3d& p_world_start);

}  // namespace anchorbench::engine
