#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "anchorbench/estimator/outlier_filter.hpp"
#include "anchorbench/estimator/solver.hpp"

namespace anchorbench::estimator {

// RANSAC pre-filtering (the filter `ransac`): n = log(1 - p) / log(1 - (1 - e)^s) subsets. The
// paper prints this formula without the log in the denominator (as printed it gives a negative
// count); its number, 1666 subsets for p = 0.95, s = 60, e = 0.1, is the corrected formula's.
struct RansacOptions {
  static constexpr int kMaxIterations = 1000000;  // a bound on the work one solve may take

  double success_probability = 0.95;  // p: of drawing at least one outlier-free subset
  int subset_size = 60;               // s: samples per subset (the paper's Table II: 60)
  double outlier_fraction = 0.1;      // e: assumed share of outliers
  double inlier_threshold_m = 0.3;    // |residual| below this counts as an inlier

  // n as a real number: +infinity where (1 - e)^s is too small to draw a clean subset in any
  // number of tries that a double can count.
  double RequiredIterations() const;
  int Iterations() const;  // n, capped at kMaxIterations (IsValid refuses more)
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

// RANSAC as an outlier filter (Table II): nothing online; at solve time the solver runs inside
// RANSAC (subsets, consensus, final fit on the inliers).
class RansacFilter : public OutlierFilter {
 public:
  RansacFilter(const RansacOptions& options, std::uint64_t seed) : options_(options), seed_(seed) {}

  bool Accept(const RangeSample&) override { return true; }
  std::shared_ptr<const Solver> AtSolve(std::shared_ptr<const Solver> solver) const override {
    return std::make_shared<RansacSolver>(options_, std::move(solver), seed_);
  }

 private:
  RansacOptions options_;
  std::uint64_t seed_;
};

}  // namespace anchorbench::estimator
