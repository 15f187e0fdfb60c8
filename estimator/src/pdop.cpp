#include "anchorbench/estimator/pdop.hpp"

namespace anchorbench::estimator {

double GeometryPdop(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                    const Eigen::Vector3d& p_world_anchor) {
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
  for (std::size_t k = 0; k < p_world_tag.size(); ++k) {
    const Eigen::Vector3d row = (p_world_tag[k] - p_world_anchor) / range_m[k];  // Eq. (3)
    information += row * row.transpose();                                      // Eq. (5)
  }
  return PdopFromInformation(information);
}

double BiasAwareDopAt(std::span<const Eigen::Vector3d> p_world_tag, const Eigen::Vector3d& p_world_anchor) {
  Eigen::Matrix3d sum_outer = Eigen::Matrix3d::Zero();
  Eigen::Vector3d sum_unit = Eigen::Vector3d::Zero();
  double n = 0.0;
  for (const Eigen::Vector3d& p : p_world_tag) {
    const Eigen::Vector3d diff = p - p_world_anchor;
    const double distance_m = diff.norm();
    if (!(distance_m > 0.0)) continue;  // a tag exactly at the point has no direction
    const Eigen::Vector3d unit = diff / distance_m;
    sum_outer.noalias() += unit * unit.transpose();
    sum_unit += unit;
    n += 1.0;
  }
  return BiasAwareDopFromSums(sum_outer, sum_unit, n);
}

}  // namespace anchorbench::estimator
