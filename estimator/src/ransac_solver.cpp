#include "anchorbench/estimator/ransac_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "anchorbench/estimator/ls_solver.hpp"
#include "anchorbench/estimator/nls_solver.hpp"
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
  if (subset_size < kMinSamplesLs || subset_size > 10000) {
    return fail("subset_size must be in [" + std::to_string(kMinSamplesLs) + ", 10000]");
  }
  if (!(outlier_fraction >= 0.0 && outlier_fraction < 1.0)) return fail("outlier_fraction must be in [0, 1)");
  if (!(inlier_threshold_m > 0.0 && inlier_threshold_m <= 1e4)) return fail("inlier_threshold_m must be in (0, 1e4]");
  if (max_subsets < 1 || max_subsets > kMaxIterations) {
    return fail("max_subsets must be in [1, " + std::to_string(kMaxIterations) + "]");
  }
  if (min_subsets < 1 || min_subsets > max_subsets) return fail("min_subsets must be in [1, max_subsets]");
  if (scheme == RansacScheme::kFullSolve && !(RequiredIterations() <= kMaxIterations)) {
    return fail("subset_size " + std::to_string(subset_size) + " with outlier_fraction " +
                std::to_string(outlier_fraction) + " needs more than " + std::to_string(kMaxIterations) +
                " subsets (n = log(1-p)/log(1-(1-e)^s)); use a smaller subset or outlier fraction");
  }
  return true;
}

int AdaptiveDraws(double inlier_share, int subset_size, double success_probability, int cap) {
  const double clean_subset = std::pow(inlier_share, subset_size);
  if (clean_subset >= 1.0) return 1;
  const double log_miss = std::log1p(-clean_subset);
  if (!(log_miss < 0.0)) return cap;  // no inliers, or too few for a double to count the draws
  const double draws = std::ceil(std::log1p(-success_probability) / log_miss);
  return static_cast<int>(std::clamp(draws, 1.0, static_cast<double>(cap)));
}

namespace {

// Draws subsets of s distinct indices: a partial Fisher-Yates over an index array that keeps the
// order the last draw left, so each draw is uniform and costs O(s). The subset's samples are
// held here, copied from the solve's.
class SubsetDrawer {
 public:
  SubsetDrawer(std::size_t n, std::size_t s, std::uint64_t seed) : rng_(seed), index_(n), p_(s), d_(s) {
    std::iota(index_.begin(), index_.end(), std::size_t{0});
  }
  void Draw(std::span<const Eigen::Vector3d> p, std::span<const double> d) {
    const std::size_t n = index_.size();
    for (std::size_t k = 0; k < p_.size(); ++k) {
      const auto pick = k + static_cast<std::size_t>(static_cast<double>(rng_() >> 11) * 0x1.0p-53 * (n - k));
      std::swap(index_[k], index_[pick]);
      p_[k] = p[index_[k]];
      d_[k] = d[index_[k]];
    }
  }
  std::span<const Eigen::Vector3d> p() const { return p_; }
  std::span<const double> d() const { return d_; }

 private:
  std::mt19937_64 rng_;
  std::vector<std::size_t> index_;
  std::vector<Eigen::Vector3d> p_;
  std::vector<double> d_;
};

Eigen::Vector4d ThetaOf(const SolveResult& fit) {
  return {fit.p_world_anchor.x(), fit.p_world_anchor.y(), fit.p_world_anchor.z(), fit.bias_m};
}

// Residuals over all samples a block at a time, for scores and consensus sets.
class Scorer {
 public:
  Scorer(std::span<const Eigen::Vector3d> p, std::span<const double> d, double threshold_m)
      : samples_(p, d), threshold_m_(threshold_m), threshold_squared_(threshold_m * threshold_m), inlier_(d.size()) {}

  // MSAC's score, sum min(r_k^2, t^2) (Torr and Zisserman 2000), with the count of |r_k| < t
  // from the same pass; or a score of +infinity as soon as the sum so far reaches `to_beat`: such
  // a hypothesis cannot win.
  struct Scored {
    double score = 0.0;
    std::size_t inliers = 0;
  };
  Scored Score(const Eigen::Vector4d& theta, double to_beat) {
    Scored scored;
    for (Eigen::Index start = 0; start < samples_.size(); start += kBlock) {
      const Eigen::Index size = std::min<Eigen::Index>(kBlock, samples_.size() - start);
      residuals_.At(samples_, start, size, theta, false);
      scored.score += residuals_.r.square().min(threshold_squared_).sum();
      if (scored.score >= to_beat) return {std::numeric_limits<double>::infinity(), 0};
      scored.inliers += static_cast<std::size_t>((residuals_.r.abs() < threshold_m_).count());
    }
    return scored;
  }

  // Marks the samples with |r_k| < t at theta; returns how many.
  std::size_t Consensus(const Eigen::Vector4d& theta) {
    std::size_t count = 0;
    for (Eigen::Index start = 0; start < samples_.size(); start += kBlock) {
      const Eigen::Index size = std::min<Eigen::Index>(kBlock, samples_.size() - start);
      residuals_.At(samples_, start, size, theta, false);
      for (Eigen::Index k = 0; k < size; ++k) {
        const bool within = std::abs(residuals_.r[k]) < threshold_m_;
        inlier_[static_cast<std::size_t>(start + k)] = within;
        count += within;
      }
    }
    return count;
  }

  // The samples Consensus marked, copied into p_out, d_out (cleared first).
  void Gather(std::span<const Eigen::Vector3d> p, std::span<const double> d, std::vector<Eigen::Vector3d>& p_out,
              std::vector<double>& d_out) const {
    p_out.clear();
    d_out.clear();
    for (std::size_t k = 0; k < inlier_.size(); ++k) {
      if (!inlier_[k]) continue;
      p_out.push_back(p[k]);
      d_out.push_back(d[k]);
    }
  }

 private:
  static constexpr Eigen::Index kBlock = 64;  // the early exit looks at the score this often
  internal::SampleArrays samples_;
  internal::ChunkResiduals residuals_;
  double threshold_m_;
  double threshold_squared_;
  std::vector<char> inlier_;
};

struct Hypothesis {
  Eigen::Vector4d theta = Eigen::Vector4d::Zero();
  double score = std::numeric_limits<double>::infinity();
  int draws = 0;
};

// LO-RANSAC's local optimization (Chum et al. 2003), our form: a minimal subset's hypothesis is
// only as good as its 6 samples, so its consensus misses good samples and keeps some bad ones.
// Plain least squares (L2 LM from the hypothesis: the consensus holds no gross outliers) on the
// consensus, the consensus at that fit, and again, until the consensus stops changing (at most
// kRounds). Leaves the final consensus in p_out, d_out.
void LocallyOptimize(Eigen::Vector4d theta, std::span<const Eigen::Vector3d> p, std::span<const double> d,
                     Scorer& scorer, std::vector<Eigen::Vector3d>& p_out, std::vector<double>& d_out) {
  constexpr int kRounds = 4;
  NlsOptions l2;
  l2.kernel = KernelMode::kL2;
  const NlsSolver least_squares(l2);
  std::size_t size = scorer.Consensus(theta);
  scorer.Gather(p, d, p_out, d_out);
  for (int round = 0; round < kRounds && d_out.size() >= static_cast<std::size_t>(kMinSamplesLs); ++round) {
    const SolveResult fit = least_squares.Solve(p_out, d_out, theta.head<3>(), theta(3));
    if (!Succeeded(fit.status) || !fit.p_world_anchor.allFinite()) return;
    theta = ThetaOf(fit);
    const std::size_t next = scorer.Consensus(theta);
    scorer.Gather(p, d, p_out, d_out);
    if (next == size) return;
    size = next;
  }
}

// The hypotheses: the linear LS of each subset, the best by MSAC score; the number of draws
// follows the best consensus so far.
Hypothesis BestHypothesis(const RansacOptions& options, std::span<const Eigen::Vector3d> p, std::span<const double> d,
                          SubsetDrawer& drawer, Scorer& scorer) {
  Hypothesis best;
  int required = options.max_subsets;
  for (; best.draws < std::max(required, options.min_subsets); ++best.draws) {
    drawer.Draw(p, d);
    const SolveResult candidate = SolveDoubleDifferenceLs(drawer.p(), drawer.d());
    if (!Succeeded(candidate.status) || !candidate.p_world_anchor.allFinite()) continue;
    const Eigen::Vector4d theta = ThetaOf(candidate);
    const Scorer::Scored scored = scorer.Score(theta, best.score);
    if (!(scored.score < best.score)) continue;
    best.theta = theta;
    best.score = scored.score;
    const double share = static_cast<double>(scored.inliers) / static_cast<double>(d.size());
    required = AdaptiveDraws(share, options.subset_size, options.success_probability, options.max_subsets);
  }
  return best;
}

}  // namespace

SolveResult RansacSolver::Solve(std::span<const Eigen::Vector3d> p, std::span<const double> d) const {
  if (d.size() <= static_cast<std::size_t>(options_.subset_size)) return inner().Solve(p, d);  // nothing to leave out
  return options_.scheme == RansacScheme::kMinimal ? SolveMinimal(p, d) : SolveFullSolve(p, d);
}

SolveResult RansacSolver::SolveMinimal(std::span<const Eigen::Vector3d> p, std::span<const double> d) const {
  SubsetDrawer drawer(d.size(), static_cast<std::size_t>(options_.subset_size), seed_);
  Scorer scorer(p, d, options_.inlier_threshold_m);
  const Hypothesis best = BestHypothesis(options_, p, d, drawer, scorer);
  SolveResult result;
  result.status = SolveStatus::kNoConvergence;
  if (!std::isfinite(best.score)) return result;
  std::vector<Eigen::Vector3d> consensus_p;
  std::vector<double> consensus_d;
  LocallyOptimize(best.theta, p, d, scorer, consensus_p, consensus_d);
  if (consensus_d.size() < static_cast<std::size_t>(kMinSamplesLs)) {
    result.status = SolveStatus::kTooFewSamples;
    return result;
  }
  result = inner().Solve(consensus_p, consensus_d);
  result.iterations += best.draws;
  return result;
}

// The Table II baseline, as before: every subset solved by `inner`, the most inliers win.
SolveResult RansacSolver::SolveFullSolve(std::span<const Eigen::Vector3d> p, std::span<const double> d) const {
  SubsetDrawer drawer(d.size(), static_cast<std::size_t>(options_.subset_size), seed_);
  Scorer scorer(p, d, options_.inlier_threshold_m);
  std::size_t best_inliers = 0;
  SolveResult best;
  const int iterations = options_.Iterations();
  for (int it = 0; it < iterations; ++it) {
    drawer.Draw(p, d);
    const SolveResult candidate = inner().Solve(drawer.p(), drawer.d());
    if (!Succeeded(candidate.status)) continue;
    const std::size_t inliers = scorer.Consensus(ThetaOf(candidate));
    if (inliers > best_inliers) {
      best_inliers = inliers;
      best = candidate;
    }
  }
  if (best_inliers < static_cast<std::size_t>(kMinSamplesLs)) {
    best.status = best_inliers == 0 ? SolveStatus::kNoConvergence : SolveStatus::kTooFewSamples;
    return best;
  }
  std::vector<Eigen::Vector3d> inlier_p;
  std::vector<double> inlier_d;
  scorer.Consensus(ThetaOf(best));
  scorer.Gather(p, d, inlier_p, inlier_d);
  SolveResult result = inner().Solve(inlier_p, inlier_d);
  result.iterations += iterations;
  return result;
}

}  // namespace anchorbench::estimator
