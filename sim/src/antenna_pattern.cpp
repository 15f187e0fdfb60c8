#include "anchorbench/sim/antenna_pattern.hpp"

#include <cmath>
#include <algorithm>
#include <numbers>

namespace anchorbench::sim {
namespace {

// Mean and mean square of each term over the sphere (z = sin el uniform in [-1, 1]):
//   sin el: 0, 1/3;  cos 2el = 1 - 2z^2: 1/3, 7/15;  cos el cos az = x: 0, 1/3;
//   cos^2 el cos 2az = x^2 - y^2: 0, 4/15;  cos^3 el cos 3az = Re (x + iy)^3: 0, 8/35;
//   sin 3el = 3z - 4z^3: 0, 17/35.
constexpr double kMean[6] = {0.0, 1.0 / 3.0, 0.0, 0.0, 0.0, 0.0};
constexpr double kMeanSquare[6] = {1.0 / 3.0, 7.0 / 15.0, 1.0 / 3.0, 4.0 / 15.0, 8.0 / 35.0, 17.0 / 35.0};

}  // namespace

AntennaPattern::AntennaPattern(double rms_m, RandomStream& rng) {
  for (int i = 0; i < kTerms; ++i) {
    const double variance = kMeanSquare[i] - kMean[i] * kMean[i];
    weight_m_[i] = rms_m * rng.Normal() / std::sqrt(variance * kTerms);
  }
  for (double& phase : phase_rad_) phase = rng.Uniform(0.0, 2.0 * std::numbers::pi);
}

double AntennaPattern::operator()(const Eigen::Vector3d& unit) const {
  const double sin_el = std::clamp(unit.z(), -1.0, 1.0);
  const double cos_el = std::sqrt(std::max(0.0, 1.0 - sin_el * sin_el));
  const double az = std::atan2(unit.y(), unit.x());
  const double terms[kTerms] = {
      sin_el,
      1.0 - 2.0 * sin_el * sin_el - kMean[1],
      cos_el * std::cos(az - phase_rad_[0]),
      cos_el * cos_el * std::cos(2.0 * (az - phase_rad_[1])),
      cos_el * cos_el * cos_el * std::cos(3.0 * (az - phase_rad_[2])),
      3.0 * sin_el - 4.0 * sin_el * sin_el * sin_el,
  };
  double bias_m = 0.0;
  for (int i = 0; i < kTerms; ++i) bias_m += weight_m_[i] * terms[i];
  return bias_m;
}

}  // namespace anchorbench::sim
