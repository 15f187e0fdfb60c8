#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/estimator/credible_covariance.hpp"

namespace anchorbench::estimator {

// Where to range from next (ours, docs/guidance.md). The certificate's region is built from sums
// over the samples' rows at the estimate (its noise part from the information J^T J, its model
// error, travel bias and link parts from J^T of their patterns: credible_covariance.hpp), and a
// sample more only adds its row to each sum. So the region after k more samples from a candidate
// tag position is a forecast in O(1) per candidate, with no truth: the same information the
// certificate judges, at its last estimate and with the noise it read from the residuals then.
//
// What it forecasts is the region's test alone, seen from the estimate (as the region from its
// axes' ends, with unit weights). The mirror's and the alternatives' evidence, the stability and a
// height prior's gap are not forecast: docs/guidance.md says when that matters.

// What the certificate judged at its last evaluation that a forecast needs (CertifiedTrigger).
struct RegionBasis {
  Eigen::Vector3d p_world_anchor = Eigen::Vector3d::Zero();
  double noise_variance_m2 = 0.0;   // per range: the correlation factor times the residual variance
                                    // (floored at the model error's), as the region from the ends
  double travel_bias_m = 0.0;       // the consistency check's (0: none)
  double height_information = 0.0;  // a height prior's 1 / sigma^2 (0: none)
  double height_weight = 0.0;       // and its weight in the solve (SolveResult::height_weight)
  bool tag_offsets = false;         // each tag's offset among the unknowns (TagBiasOptions::estimate)
  double region_chi2 = 0.0;         // the 3-dof chi-square quantile at the certificate's confidence
  double accuracy_m = 0.0;          // D: the radius the region must come within
  CovarianceOptions covariance;
};

// One candidate's forecast.
struct CandidateForecast {
  Eigen::Vector3d p_world_candidate = Eigen::Vector3d::Zero();
  double region_m = 0.0;            // the region's radius after `samples` more from the candidate
  double samples_to_certify = 0.0;  // the fewest samples from it that bring the region within D
                                    // (+inf: none up to the search's limit, or never: the model error)
};

class RegionForecast {
 public:
  // O(N T^2): the sums over the samples (the anchor's buffered tag positions, with their tags).
  RegionForecast(const RegionBasis& basis, std::span<const Eigen::Vector3d> p_world_tag, std::span<const int> tag_id);

  // The region's radius (m) after `samples` more ranges from `p_world_candidate`, by the tag of the
  // last sample (+inf where the information stays singular). O(T^3): a handful of tags at most.
  double RegionAfter(const Eigen::Vector3d& p_world_candidate, double samples) const;
  double region_m() const { return region_now_m_; }  // RegionAfter(any, 0)
  // The fewest samples (an integer up to max_samples, found by doubling and then bisection) that
  // bring RegionAfter within D; +inf where max_samples do not.
  double SamplesToCertify(const Eigen::Vector3d& p_world_candidate, double max_samples = 1e5) const;
  // The `best` candidates by their region after `samples` more (ties: the earlier candidate),
  // each with its samples to certify. O(candidates log candidates) + O(best log max_samples).
  std::vector<CandidateForecast> Rank(std::span<const Eigen::Vector3d> p_world_candidate, double samples,
                                      std::size_t best) const;
  const RegionBasis& basis() const { return basis_; }

 private:
  double LargestVariance(const Eigen::MatrixXd& information, const ErrorSums& sums) const;

  RegionBasis basis_;
  ErrorSums sums_;                    // the added part's
  Eigen::MatrixXd information_;       // of (p_A, gamma[, each later tag's offset]), unit weights
  std::size_t last_tag_index_ = 0;   // of the last sample's tag among the offset tags (0: the first, no column)
  std::size_t last_link_index_ = 0;  // and in sums_.tags (without links: none to add to)
  double region_now_m_ = 0.0;
};

// A default set of candidates: a cube grid of (2 steps + 1)^3 points around `p_world_tag`, `reach_m`
// to each side (steps >= 1), the tag's own position among them.
std::vector<Eigen::Vector3d> CandidateGrid(const Eigen::Vector3d& p_world_tag, double reach_m, int steps);

}  // namespace anchorbench::estimator
