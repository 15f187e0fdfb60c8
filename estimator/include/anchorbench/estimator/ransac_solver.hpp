#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/solver.hpp"

namespace anchorbench::estimator {

// RANSAC pre-filtering (filter kind ransac): n = log(1 - p) / log(1 - (1 - e)^s) subsets.
struct RansacOptions {
  double success_probability = 0.95;  // p: of drawing at least one outlier-free subset
  int subset_size = 60;               // s: samples per subset (the paper's Table II: 60)
  double outlier_fraction = 0.1;      // e: assumed share of outliers
  double inlier_threshold_m = 0.3;    // |residual| below this counts as an inlier

  int Iterations() const;
  bool IsValid(std::string* why) const;
};

// RANSAC around a solver, as the baseline of the paper's Table II (after Jung et al. 2024):
// options.Iterations() random subsets of subset_size samples, each solved by `inner`; the subset
// whose solution has the most inliers (|r_k| < inlier_threshold_m over all samples) wins, and
// `inner` is run once more on its inliers. Subsets come from std::mt19937_64 (a sequence the C++
// standard fixes) seeded per solver, with our own index mapping, so results repeat anywhere.
class RansacSolver : public Solver {
 public:
  RansacSolver(const RansacOptions& options, std::shared_ptr<const Solver> inner, std::uint64_t seed)
      : options_(options), inner_(std::move(inner)), seed_(seed) {}

  SolveResult Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const override;

 private:
  RansacOptions options_;
  std::shared_ptr<const Solver> inner_;
  std::uint64_t seed_;
};

}  // namespace anchorbench::estimator
