#include "anchorbench/estimator/tag_biases.hpp"

#include <algorithm>
#include <cmath>

#include "numerics.hpp"

namespace anchorbench::estimator {

bool TagBiasOptions::IsValid(std::string* why) const {
  if (iterations < 1 || iterations > 50) {
    if (why) *why = "iterations must be in [1, 50]";
    return false;
  }
  return true;
}

SolveResult SolveWithTagBiases(const Solver& solver, std::span<const Eigen::Vector3d> p_world_tag,
                               std::span<const double> range_m, std::span<const int> tag_id,
                               const TagBiasOptions& options, std::vector<double>* offsets_m) {
  std::vector<int> tags;
  if (options.estimate && tag_id.size() == range_m.size()) {
    for (const int tag : tag_id) {
      if (std::find(tags.begin(), tags.end(), tag) == tags.end()) tags.push_back(tag);
    }
  }
  if (offsets_m) offsets_m->assign(std::max<std::size_t>(tags.size(), 1), 0.0);
  if (tags.size() < 2) return solver.Solve(p_world_tag, range_m);
  std::vector<std::size_t> index(range_m.size());
  for (std::size_t k = 0; k < range_m.size(); ++k) {
    index[k] = static_cast<std::size_t>(std::find(tags.begin(), tags.end(), tag_id[k]) - tags.begin());
  }
  std::vector<double> offset(tags.size(), 0.0), corrected(range_m.begin(), range_m.end());
  std::vector<double> sum(tags.size()), count(tags.size());
  SolveResult result;
  for (int iteration = 0; iteration < options.iterations; ++iteration) {
    for (std::size_t k = 0; k < range_m.size(); ++k) corrected[k] = range_m[k] - offset[index[k]];
    result = solver.Solve(p_world_tag, corrected);
    if (!Succeeded(result.status)) return result;
    // Each tag's mean residual at the estimate, against the first tag's (its offset stays 0).
    std::fill(sum.begin(), sum.end(), 0.0);
    std::fill(count.begin(), count.end(), 0.0);
    for (std::size_t k = 0; k < range_m.size(); ++k) {
      sum[index[k]] += range_m[k] - (p_world_tag[k] - result.p_world_anchor).norm() - result.bias_m;
      count[index[k]] += 1.0;
    }
    for (std::size_t t = 1; t < tags.size(); ++t) offset[t] = sum[t] / count[t] - sum[0] / count[0] + offset[0];
  }
  // Each estimated offset's uncertainty, sigma^2 / n_t, through its tag's rows (A^-1 J^T e_t).
  Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
  std::vector<Eigen::Vector4d> jt(tags.size(), Eigen::Vector4d::Zero());
  double squares = 0.0;
  for (std::size_t k = 0; k < range_m.size(); ++k) {
    const Eigen::Vector3d diff = p_world_tag[k] - result.p_world_anchor;
    const double distance_m = diff.norm();
    if (!(distance_m > 0.0)) continue;
    Eigen::Vector4d j;
    j << -diff / distance_m, 1.0;
    a.noalias() += j * j.transpose();
    jt[index[k]] += j;
    const double r = distance_m + result.bias_m + offset[index[k]] - range_m[k];
    squares += r * r;
  }
  Eigen::Matrix4d a_inverse;
  if (internal::InvertNormalMatrix(a, &a_inverse) && range_m.size() > 4 + tags.size()) {
    const double variance = squares / static_cast<double>(range_m.size() - 4 - (tags.size() - 1));
    Eigen::Matrix4d added = Eigen::Matrix4d::Zero();
    for (std::size_t t = 1; t < tags.size(); ++t) added.noalias() += variance / count[t] * jt[t] * jt[t].transpose();
    result.covariance += a_inverse * added * a_inverse;
  }
  if (offsets_m) *offsets_m = offset;
  return result;
}

}  // namespace anchorbench::estimator
