#include "anchorbench/estimator/ransac_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "residual_arrays.hpp"

namespace anchorbench::estimator {

double RansacOptions::RequiredIterations() const {
  const double clean_subset = std::pow(1.0 - outlier_fraction, subset_size);
  if (clean_subset >= 1.0) return 1.0;
  const double log_miss = std::log(1.0 - clean_subset);
  // (1 - e)^s below the double's resolution near 1: no number of tries finds a clean subset.
  if (!(log_miss < 0.0)) return std::numeric_limits<double>::infinity();
  return std::ceil(std::log(1.0 - success_probability) / log_miss);
}

int RansacOptions::Iterations() const {
  return static_cast<int>(std::min(RequiredIterations(), static_cast<double>(kMaxIterations)));
}

bool RansacOptions::IsValid(std::string* why) const {
  auto fail = [why](std::string message) {
    if (why) *why = std::move(message);
    return false;
  };
  if (!(success_probability > 0.0 && success_probability < 1.0)) return fail("success_probability must be in (0, 1)");
  if (subset_size < kMinSamplesLs) return fail("subset_size must be >= " + std::to_string(kMinSamplesLs));
  if (!(outlier_fraction >= 0.0 && outlier_fraction < 1.0)) return fail("outlier_fraction must be in [0, 1)");
  if (!(inlier_threshold_m > 0.0) || !std::isfinite(inlier_threshold_m)) return fail("inlier_threshold_m must be > 0");
  if (!(RequiredIterations() <= kMaxIterations)) {
    return fail("subset_size " + std::to_string(subset_size) + " with outlier_fraction " +
                std::to_string(outlier_fraction) + " needs more than " + std::to_string(kMaxIterations) +
                " subsets (n = log(1-p)/log(1-(1-e)^s)); use a smaller subset or outlier fraction");
  }
  return true;
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
  const internal::SampleArrays samples(p, d);
  internal::ChunkResiduals residuals;
  // Consensus of a fit: whether each sample's residual is within the threshold, a chunk at a time.
  std::vector<char> inlier(n);
  auto inliers_of = [&](const SolveResult& fit) {
    const Eigen::Vector4d theta(fit.p_world_anchor.x(), fit.p_world_anchor.y(), fit.p_world_anchor.z(), fit.bias_m);
    std::size_t count = 0;
    for (Eigen::Index start = 0; start < samples.size(); start += kChunk) {
      const Eigen::Index size = std::min<Eigen::Index>(kChunk, samples.size() - start);
      residuals.At(samples, start, size, theta, false);
      for (Eigen::Index k = 0; k < size; ++k) {
        const bool within = std::abs(residuals.r[k]) < options_.inlier_threshold_m;
        inlier[static_cast<std::size_t>(start + k)] = within;
        count += within;
      }
    }
    return count;
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
    const std::size_t inliers = inliers_of(candidate);
    if (inliers > best_inliers) {
      best_inliers = inliers;
      best = candidate;
    }
  }
  if (best_inliers < static_cast<std::size_t>(kMinSamplesLs)) {
    best.status = best_inliers == 0 ? SolveStatus::kNoConvergence : SolveStatus::kTooFewSamples;
    return best;
  }
  inliers_of(best);
  for (std::size_t k = 0; k < n; ++k) {
    if (inlier[k]) {
      inlier_p.push_back(p[k]);
      inlier_d.push_back(d[k]);
    }
  }
  SolveResult result = inner_->Solve(inlier_p, inlier_d);
  result.iterations += iterations;
  return result;
}

}  // namespace anchorbench::estimator
