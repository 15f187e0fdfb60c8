#include "dop_waypoints.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Cholesky>

namespace anchorbench::engine {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Eigen::Vector4d RowAt(const Eigen::Vector3d& p_world_tag, const Eigen::Vector3d& p_world_anchor) {
  const Eigen::Vector3d diff = p_world_tag - p_world_anchor;
  const double distance_m = diff.norm();
  Eigen::Vector4d row = Eigen::Vector4d::Zero();
  if (distance_m > 0.0) row << -diff / distance_m, 1.0;
  return row;
}

// sqrt(trace of the position block of the inverse information): +inf where it is singular.
double Pdop(const Eigen::Matrix4d& information) {
  const Eigen::LDLT<Eigen::Matrix4d> ldlt(information);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive() || ldlt.vectorD().minCoeff() <= 1e-12 * information.trace()) {
    return kInf;
  }
  const Eigen::Matrix4d covariance = ldlt.solve(Eigen::Matrix4d::Identity());
  return std::sqrt(covariance.topLeftCorner<3, 3>().trace());
}

// The summed PDOP with `samples` more from `p`; an anchor still singular counts a large constant,
// so that a waypoint that makes it observable is worth more than any other improvement.
double CostWith(const std::vector<PlannedAnchor>& anchors, const Eigen::Vector3d& p, double samples) {
  constexpr double kSingularPdop = 1e6;
  double cost = 0.0;
  for (const PlannedAnchor& a : anchors) {
    const Eigen::Vector4d row = RowAt(p, a.p_world_anchor);
    cost += std::min(kSingularPdop, Pdop(a.information + samples * row * row.transpose()));
  }
  return cost;
}

}  // namespace

Eigen::Matrix4d RangeInformation(std::span<const Eigen::Vector3d> p_world_tag, const Eigen::Vector3d& p_world_anchor) {
  Eigen::Matrix4d information = Eigen::Matrix4d::Zero();
  for (const Eigen::Vector3d& p : p_world_tag) {
    const Eigen::Vector4d row = RowAt(p, p_world_anchor);
    information.noalias() += row * row.transpose();
  }
  return information;
}

std::vector<Eigen::Vector3d> PlanDopWaypoints(std::vector<PlannedAnchor> anchors,
                                              std::span<const Eigen::Vector3d> p_world_candidate, int count,
                                              double samples_each, const Eigen::Vector3d& p_world_start) {
  std::vector<Eigen::Vector3d> chosen;
  std::vector<bool> taken(p_world_candidate.size(), false);
  for (int w = 0; w < count && !anchors.empty(); ++w) {
    std::size_t best = p_world_candidate.size();
    double best_cost = kInf;
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
    for (PlannedAnchor& a : anchors) {
      const Eigen::Vector4d row = RowAt(p_world_candidate[best], a.p_world_anchor);
      a.information.noalias() += samples_each * row * row.transpose();
    }
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

}  // namespace anchorbench::engine
