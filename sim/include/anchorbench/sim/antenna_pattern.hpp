#pragma once

#include <Eigen/Core>

#include "anchorbench/sim/random_stream.hpp"

namespace anchorbench::sim {

// A radio's direction-dependent range bias (its antenna's group delay over the sphere): a smooth
// random function of the direction's azimuth az and elevation el, six low-order terms
//   sin el, cos 2el, cos el cos(az - phi1), cos^2 el cos 2(az - phi2), cos^3 el cos 3(az - phi3), sin 3el
// (each made zero-mean and unit mean-square over the sphere), with N(0, 1) weights, scaled so that
// its expected RMS over the sphere is `rms_m`. Public recordings show per-anchor medians of range
// minus truth of +-0.05-0.08 m that change with the viewing direction (docs/method.md); a constant
// bias and white noise miss them. Zero amplitude draws nothing.
class AntennaPattern {
 public:
  AntennaPattern() = default;
  AntennaPattern(double rms_m, RandomStream& rng);
  // The bias in metres for a unit direction (in the radio's frame; world axes for anchors).
  double operator()(const Eigen::Vector3d& unit) const;

 private:
  static constexpr int kTerms = 6;
  double weight_m_[kTerms] = {};
  double phase_rad_[3] = {};
};

}  // namespace anchorbench::sim
