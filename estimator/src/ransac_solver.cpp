#include "anchorbench/estimator/ransac_solver.hpp"

#include <cmath>
#include <numeric>
#include <random>
#include <vector>

namespace anchorbench::estimator {

int RansacOptions::Iterations() const {
  const double clean_subset = std::pow(1.0 - outlier_fraction, subset_size);
  if (clean_subset >= 1.0) return 1;
  return static_cast<int>(std::ceil(std::log(1.0 - success_probability) / std::log(1.0 - clean_subset)));
}

bool RansacOptions::IsValid(std::string* why) const {
  const bool ok = success_probability > 0.0 && success_probability < 1.0 && subset_size >= 6 &&
                  outlier_fraction >= 0.0 && outlier_fraction < 1.0 && inlier_threshold_m > 0.0 &&
                  Iterations() <= 1000000;
  if (!ok && why) {
    *why = "ransac needs 0 < success_probability < 1, subset_size >= 6, 0 <= outlier_fraction < 1, "
           "inlier_threshold_m > 0, and at most 1e6 iterations";
  }
  return ok;
}

SolveResult RansacSolver::Solve(std::span<const Eigen::Vector3d> p, std::span<const double> d) const {
  const std::size_t n = d.size();
  const std::size_t s = static_cast<std::size_t>(options_.subset_size);
  if (n <= s) return inner_->Solve(p, d);  // no room to leave anything out
  std::mt19937_64 rng(seed_);
  std::vector<std::size_t> index(n);
  std::iota(index.begin(), index.end(), std::size_t{0});
  std::vector<Eigen::Vector3d> subset_p(s), inlier_p;
  std::vector<double> subset_d(s), inlier_d;
  auto is_inlier = [&](std::size_t k, const SolveResult& fit) {
    return std::abs((p[k] - fit.p_world_anchor).norm() + fit.bias_m - d[k]) < options_.inlier_threshold_m;
  };
  std::size_t best_inliers = 0;
  SolveResult best;
  const int iterations = options_.Iterations();
  for (int it = 0; it < iterations; ++it) {
    // Partial Fisher-Yates: s distinct samples, uniform from whatever order the last draw left.
    for (std::size_t k = 0; k < s; ++k) {
      const auto pick = k + static_cast<std::size_t>(static_cast<double>(rng() >> 11) * 0x1.0p-53 * (n - k));
      std::swap(index[k], index[pick]);
      subset_p[k] = p[index[k]];
      subset_d[k] = d[index[k]];
    }
    const SolveResult candidate = inner_->Solve(subset_p, subset_d);
    if (!Succeeded(candidate.status)) continue;
    std::size_t inliers = 0;
    for (std::size_t k = 0; k < n; ++k) inliers += is_inlier(k, candidate);
    if (inliers > best_inliers) {
      best_inliers = inliers;
      best = candidate;
    }
  }
  if (best_inliers < 6) {
    best.status = best_inliers == 0 ? SolveStatus::kNoConvergence : SolveStatus::kTooFewSamples;
    return best;
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (is_inlier(k, best)) {
      inlier_p.push_back(p[k]);
      inlier_d.push_back(d[k]);
    }
  }
  SolveResult result = inner_->Solve(inlier_p, inlier_d);
  result.iterations += iterations;
  return result;
}

}  // namespace anchorbench::estimator
