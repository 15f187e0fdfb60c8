#pragma once
// Odometry as a robot's dead reckoning reports it, simulated from a true trajectory (ours,
// docs/navigation.md): each step's displacement seen through a heading that drifts and with a
// velocity bias that drifts, both random walks, plus white noise on the step.
//   delta_psi_k = delta_psi_{k-1} + sigma_heading sqrt(dt) w       (yaw error, rad)
//   b_k         = b_{k-1} + sigma_bias sqrt(dt) w                   (world-frame velocity bias, m/s)
//   d_k         = Rz(delta_psi_k) (p_k - p_{k-1}) + b_k dt + sigma_step sqrt(dt) w
// The errors start at zero. Magnitudes of a wheel odometry and of a VIO are configs, not code.

#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/sim/random_stream.hpp"

namespace anchorbench::nav {

struct OdometryDrift {
  double sigma_bias_mps_per_sqrt_s = 0.002;     // the velocity bias's random walk
  double sigma_heading_rad_per_sqrt_s = 0.001;  // the heading error's random walk
  double sigma_step_m_per_sqrt_s = 0.01;        // white noise of each step's displacement

  bool IsValid(std::string* why) const;
};

struct OdometryStep {
  double t_s = 0.0;                                        // the step ends here
  double dt_s = 0.0;
  Eigen::Vector3d displacement_m = Eigen::Vector3d::Zero();  // as the odometry reports it
};

// One step per pose after the first. Throws std::invalid_argument if times do not increase.
std::vector<OdometryStep> SimulateOdometry(std::span<const double> t_s, std::span<const Eigen::Vector3d> p_world_tag,
                                           const OdometryDrift& drift, sim::RandomStream& rng);

// Rz(angle): a rotation about the world's z axis.
Eigen::Matrix3d Yaw(double angle_rad);

}  // namespace anchorbench::nav
