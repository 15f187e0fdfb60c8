#include "anchorbench/estimator/pdop.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Core>

#include "numerics.hpp"

namespace anchorbench::estimator {

double PdopFromInformation(const Eigen::Matrix3d& information) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // tr(I^-1) = (sum of the principal 2x2 minors) / det(I) for a symmetric 3x3 matrix.
  const Eigen::Matrix3d& m = information;
  const double minor_00 = m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1);
  const double minor_11 = m(0, 0) * m(2, 2) - m(0, 2) * m(2, 0);
  const double minor_22 = m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
  const double det = m(0, 0) * minor_00 - m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
                     m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
  const double trace = m.trace();
  // Rank-deficient (e.g. collinear tag positions): det vanishes relative to the scale trace^3.
  if (!(trace > 0.0) || !(det > internal::kMinRelativeDeterminant * trace * trace * trace)) return kInf;
  const double trace_of_inverse = (minor_00 + minor_11 + minor_22) / det;
  if (!(trace_of_inverse > 0.0) || !std::isfinite(trace_of_inverse)) return kInf;
  return std::sqrt(trace_of_inverse);  // Eq. (2)
}

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
