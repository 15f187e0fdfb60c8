#pragma once

#include <span>

#include <Eigen/Core>

namespace anchorbench::estimator {

// sqrt(tr(I^-1)) for a 3x3 information matrix; +infinity when it is numerically singular.
double PdopFromInformation(const Eigen::Matrix3d& information);

// Eq. (2)-(3): PDOP with rows (p_k - p_A)^T / d_k for a given anchor position and ranges.
// With an estimated p_A this is the "LS PDOP" / "NLS PDOP" of Sec. IV-B.
double GeometryPdop(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                    const Eigen::Vector3d& p_world_anchor);

}  // namespace anchorbench::estimator
