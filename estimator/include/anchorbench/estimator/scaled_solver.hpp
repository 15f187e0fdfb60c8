#pragma once

#include <memory>
#include <span>
#include <string>

#include "anchorbench/estimator/solver.hpp"

namespace anchorbench::estimator {

// A range scale factor as a fifth unknown (ours; the authors' library estimates one by default):
// d = (1 + s) ||p_U - p_A|| + gamma + eta. Public recordings show distance slopes of up to 4.5%.
struct ScaleOptions {
  bool estimate = false;
  double max_sigma = 0.01;  // the scale is used only where the data pin it to this (1-sigma)
  double max_scale = 0.2;   // |s| beyond this is not a clock or antenna error but a bad fit

  bool IsValid(std::string* why) const;
};

// Any solver of (p_A, gamma) made to estimate s too, by profiling: for a given s the ranges
// d / (1 + s) are the 4-unknown problem (gamma / (1 + s) its bias), so s is found on a parabola
// through the profile cost C(s) = (1 + s)^2 min sum r^2 at s = 0 and +-h, and refined once at its
// vertex. Its own observability check: the profile's curvature gives sigma_s = sigma / sqrt(a)
// (a the parabola's coefficient, sigma^2 = C / (N - 5)); where sigma_s > max_sigma, or the vertex
// is beyond max_scale, or the parabola opens downwards, the 4-unknown solve stands (s = 0,
// range_scale_observable = false). With s, the covariance gains sigma_s^2 (d theta/ds)(...)^T.
// Cost: four solves of the inner solver.
class ScaledSolver : public SolverDecorator {
 public:
  ScaledSolver(std::shared_ptr<const Solver> inner, const ScaleOptions& options)
      : SolverDecorator(std::move(inner)), options_(options) {}
  SolveResult Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const override;

 private:
  ScaleOptions options_;
};

}  // namespace anchorbench::estimator
