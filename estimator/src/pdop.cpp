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

}  // namespace anchorbench::estimator
