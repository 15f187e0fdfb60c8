#include "anchorbench/estimator/guidance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "anchorbench/estimator/tag_biases.hpp"

namespace anchorbench::estimator {
namespace {

// The index of the last sample's tag in `tags` (0 where it is not there, or there is none).
std::size_t IndexOf(const std::vector<int>& tags, std::span<const int> tag_id) {
  if (tag_id.empty()) return 0;
  const auto found = std::find(tags.begin(), tags.end(), tag_id.back());
  return found == tags.end() ? 0 : static_cast<std::size_t>(found - tags.begin());
}

}  // namespace

RegionForecast::RegionForecast(const RegionBasis& basis, std::span<const Eigen::Vector3d> p_world_tag,
                               std::span<const int> tag_id)
    : basis_(basis),
      sums_(SumErrorRows(p_world_tag, tag_id, basis.p_world_anchor, basis.covariance, basis.travel_bias_m)) {
  const std::vector<int> tags = OffsetTags(tag_id, p_world_tag.size(), basis.tag_offsets);
  information_ = TagInformation(p_world_tag, tags.size() > 1 ? tag_id : std::span<const int>(), tags,
                                basis.p_world_anchor);
  last_tag_index_ = tags.size() > 1 ? IndexOf(tags, tag_id) : 0;
  last_link_index_ = IndexOf(sums_.tags, tag_id);  // 0 without links: none to add to
  region_now_m_ = std::sqrt(basis_.region_chi2 * LargestVariance(information_, sums_));
}

double RegionForecast::RegionAfter(const Eigen::Vector3d& p_world_candidate, double samples) const {
  if (!(samples > 0.0)) return region_now_m_;
  const Eigen::Vector3d diff = p_world_candidate - basis_.p_world_anchor;
  const double distance_m = diff.norm();
  if (!(distance_m > 0.0)) return region_now_m_;  // at the anchor: a range says nothing of direction
  // Each sample's row [-u, 1, e_tag] joins the information; the added part's sums take it too.
  Eigen::Vector4d j;
  j << -diff / distance_m, 1.0;
  Eigen::MatrixXd information = information_;
  information.topLeftCorner<4, 4>().noalias() += samples * j * j.transpose();
  if (last_tag_index_ > 0) {  // the tag's own offset column
    const auto c = 3 + static_cast<Eigen::Index>(last_tag_index_);
    information.block<4, 1>(0, c) += samples * j;
    information.block<1, 4>(c, 0) += samples * j.transpose();
    information(c, c) += samples;
  }
  ErrorSums sums = sums_;
  sums.AddRow(diff / distance_m, j, basis_.covariance.model_error_degree, samples, last_link_index_);
  return std::sqrt(basis_.region_chi2 * LargestVariance(information, sums));
}

double RegionForecast::LargestVariance(const Eigen::MatrixXd& information, const ErrorSums& sums) const {
  // As the certificate's region from its axes' ends.
  return LargestPositionVariance(information, basis_.noise_variance_m2, basis_.height_information,
                                 AddedCovariance(sums, basis_.covariance, basis_.travel_bias_m, basis_.height_weight));
}

double RegionForecast::SamplesToCertify(const Eigen::Vector3d& p_world_candidate, double max_samples) const {
  const auto within = [&](double samples) { return RegionAfter(p_world_candidate, samples) <= basis_.accuracy_m; };
  if (within(0.0)) return 0.0;
  // Doubling to a count that certifies, then bisection between it and the one before.
  double passing = 1.0;
  while (!within(passing)) {
    if (passing >= max_samples) return std::numeric_limits<double>::infinity();
    passing = std::min(2.0 * passing, max_samples);
  }
  double failing = std::floor(passing / 2.0);
  while (passing - failing > 1.0) {
    const double middle = std::floor(0.5 * (passing + failing));
    (within(middle) ? passing : failing) = middle;
  }
  return passing;
}

std::vector<CandidateForecast> RegionForecast::Rank(std::span<const Eigen::Vector3d> p_world_candidate,
                                                    double samples, std::size_t best) const {
  std::vector<double> region_m(p_world_candidate.size());
  for (std::size_t c = 0; c < p_world_candidate.size(); ++c) region_m[c] = RegionAfter(p_world_candidate[c], samples);
  std::vector<std::size_t> order(p_world_candidate.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const std::size_t kept = std::min(best, order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(kept), order.end(),
                    [&](std::size_t a, std::size_t b) { return region_m[a] < region_m[b] || (region_m[a] == region_m[b] && a < b); });
  std::vector<CandidateForecast> ranked;
  ranked.reserve(kept);
  for (std::size_t i = 0; i < kept; ++i) {
    const std::size_t c = order[i];
    ranked.push_back({p_world_candidate[c], region_m[c], SamplesToCertify(p_world_candidate[c])});
  }
  return ranked;
}

std::vector<Eigen::Vector3d> CandidateGrid(const Eigen::Vector3d& p_world_tag, double reach_m, int steps) {
  steps = std::max(steps, 1);
  const double step_m = reach_m / steps;
  std::vector<Eigen::Vector3d> grid;
  grid.reserve(static_cast<std::size_t>((2 * steps + 1) * (2 * steps + 1) * (2 * steps + 1)));
  for (int i = -steps; i <= steps; ++i) {
    for (int j = -steps; j <= steps; ++j) {
      for (int k = -steps; k <= steps; ++k) grid.push_back(p_world_tag + step_m * Eigen::Vector3d(i, j, k));
    }
  }
  return grid;
}

}  // namespace anchorbench::estimator
