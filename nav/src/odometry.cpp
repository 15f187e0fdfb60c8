#include "anchorbench/nav/odometry.hpp"

#include <cmath>
#include <stdexcept>

namespace anchorbench::nav {

bool OdometryDrift::IsValid(std::string* why) const {
  const bool ok = sigma_bias_mps_per_sqrt_s >= 0.0 && sigma_heading_rad_per_sqrt_s >= 0.0 &&
                  sigma_step_m_per_sqrt_s >= 0.0 && std::isfinite(sigma_bias_mps_per_sqrt_s) &&
                  std::isfinite(sigma_heading_rad_per_sqrt_s) && std::isfinite(sigma_step_m_per_sqrt_s);
  if (!ok && why) *why = "the odometry's sigmas must be finite and >= 0";
  return ok;
}

Eigen::Matrix3d Yaw(double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  Eigen::Matrix3d r;
  r << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  return r;
}

std::vector<OdometryStep> SimulateOdometry(std::span<const double> t_s, std::span<const Eigen::Vector3d> p_world_tag,
                                           const OdometryDrift& drift, sim::RandomStream& rng) {
  std::vector<OdometryStep> steps;
  double heading_error = 0.0;
  Eigen::Vector3d bias = Eigen::Vector3d::Zero();
  for (std::size_t k = 1; k < t_s.size(); ++k) {
    const double dt = t_s[k] - t_s[k - 1];
    if (!(dt > 0.0)) throw std::invalid_argument("odometry: pose times must increase");
    const double root_dt = std::sqrt(dt);
    heading_error += drift.sigma_heading_rad_per_sqrt_s * root_dt * rng.Normal();
    for (int i = 0; i < 3; ++i) bias[i] += drift.sigma_bias_mps_per_sqrt_s * root_dt * rng.Normal();
    Eigen::Vector3d noise;
    for (int i = 0; i < 3; ++i) noise[i] = drift.sigma_step_m_per_sqrt_s * root_dt * rng.Normal();
    steps.push_back({t_s[k], dt, Yaw(heading_error) * (p_world_tag[k] - p_world_tag[k - 1]) + bias * dt + noise});
  }
  return steps;
}

}  // namespace anchorbench::nav
