#include "anchorbench/estimator/tag_biases.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

#include "numerics.hpp"

namespace anchorbench::estimator {

bool TagBiasOptions::IsValid(std::string* why) const {
  if (iterations < 1 || iterations > 50) {
    if (why) *why = "iterations must be in [1, 50]";
    return false;
  }
  return true;
}

namespace {
constexpr double kSettledOffsetM = 1e-4;
}  // namespace

std::vector<int> TagsInOrder(std::span<const int> tag_id) {
  std::vector<int> tags;
  for (const int tag : tag_id) {
    if (std::find(tags.begin(), tags.end(), tag) == tags.end()) tags.push_back(tag);
  }
  return tags;
}

std::vector<int> OffsetTags(std::span<const int> tag_id, std::size_t samples, bool estimate) {
  std::vector<int> tags;
  if (estimate && tag_id.size() == samples) tags = TagsInOrder(tag_id);
  if (tags.empty()) tags.push_back(0);
  return tags;
}

SolveResult SolveWithTagBiases(const Solver& solver, std::span<const Eigen::Vector3d> p_world_tag,
                               std::span<const double> range_m, std::span<const int> tag_id,
                               const TagBiasOptions& options, std::vector<double>* offsets_m,
                               std::vector<double>* corrected_m) {
  const std::vector<int> tags = OffsetTags(tag_id, range_m.size(), options.estimate);
  if (offsets_m) offsets_m->assign(tags.size(), 0.0);
  if (corrected_m) corrected_m->assign(range_m.begin(), range_m.end());
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
    // After the first solve the ranges change by the offsets' update only: start from its estimate.
    result = iteration == 0 ? solver.Solve(p_world_tag, corrected) : solver.SolveNear(p_world_tag, corrected, result);
    if (!Succeeded(result.status)) return result;
    // An estimate short of its minimum (the iteration budget spent: a flat path's height valley) has
    // residuals that say nothing about the offsets, and another solve would crawl the same valley.
    if (result.status != SolveStatus::kConverged) break;
    // Each tag's mean residual at the estimate, against the first tag's (its offset stays 0).
    std::fill(sum.begin(), sum.end(), 0.0);
    std::fill(count.begin(), count.end(), 0.0);
    for (std::size_t k = 0; k < range_m.size(); ++k) {
      sum[index[k]] += range_m[k] - (p_world_tag[k] - result.p_world_anchor).norm() - result.bias_m;
      count[index[k]] += 1.0;
    }
    double change_m = 0.0;
    for (std::size_t t = 1; t < tags.size(); ++t) {
      const double updated = sum[t] / count[t] - sum[0] / count[0] + offset[0];
      change_m = std::max(change_m, std::abs(updated - offset[t]));
      offset[t] = updated;
    }
    // Settled (far below any range noise): one more solve would move nothing that matters.
    if (iteration > 0 && change_m < kSettledOffsetM) break;
  }
  // The covariance of (p_A, gamma) with the offsets estimated beside them: the (p_A, gamma) block of
  // s^2 H^-1, H the information of (p_A, gamma, delta_2..delta_T) (rows [-u_k, 1, e_tag(k)]). Where
  // the tags see the anchor alike (a rig early in a narrow cone), an offset trades with the
  // position, which this keeps and a per-offset variance would not.
  const Eigen::MatrixXd information = TagInformation(p_world_tag, tag_id, tags, result.p_world_anchor);
  double squares = 0.0;
  for (std::size_t k = 0; k < range_m.size(); ++k) {
    const double r = (p_world_tag[k] - result.p_world_anchor).norm() + result.bias_m + offset[index[k]] - range_m[k];
    squares += r * r;
  }
  const double dof = static_cast<double>(range_m.size()) - 3.0 - static_cast<double>(tags.size());
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(information);
  const Eigen::MatrixXd inverse = ldlt.solve(Eigen::MatrixXd::Identity(information.rows(), information.cols()));
  if (dof > 0.0 && ldlt.info() == Eigen::Success && inverse.allFinite() && inverse.diagonal().minCoeff() > 0.0) {
    // The solver's own covariance (robust, where it is) scaled by the ratio of the joint block to
    // the 4-unknown one: the offsets' share of the uncertainty, on the solver's noise model.
    const Eigen::Matrix4d joint = squares / dof * inverse.topLeftCorner<4, 4>();
    Eigen::Matrix4d alone_inverse;
    if (internal::InvertNormalMatrix(information.topLeftCorner<4, 4>(), &alone_inverse)) {
      result.covariance += joint - squares / dof * alone_inverse;
    }
  } else {
    result.status = SolveStatus::kDegenerateGeometry;  // an offset the data cannot tell from the position
  }
  if (offsets_m) *offsets_m = offset;
  if (corrected_m) {
    for (std::size_t k = 0; k < range_m.size(); ++k) (*corrected_m)[k] = range_m[k] - offset[index[k]];
  }
  return result;
}

Eigen::MatrixXd TagInformation(std::span<const Eigen::Vector3d> p_world_tag, std::span<const int> tag_id,
                               const std::vector<int>& tags, const Eigen::Vector3d& p_world_anchor) {
  // Rows [-u_k, 1, e_tag(k)]: the (p_A, gamma) block, each extra tag's column (the sum of its rows'
  // first four entries) and its count; summed in fixed sizes (no per-sample dynamic products).
  const std::size_t extra = tags.empty() ? 0 : tags.size() - 1;
  Eigen::Matrix4d core = Eigen::Matrix4d::Zero();
  std::vector<Eigen::Vector4d> columns(extra, Eigen::Vector4d::Zero());
  Eigen::Vector4d row;
  for (std::size_t k = 0; k < p_world_tag.size(); ++k) {
    const Eigen::Vector3d diff = p_world_tag[k] - p_world_anchor;
    const double distance_m = diff.norm();
    if (!(distance_m > 0.0)) continue;
    row << -diff / distance_m, 1.0;
    core.noalias() += row * row.transpose();
    if (extra > 0 && k < tag_id.size()) {  // none: one tag, no offsets
      const auto t = static_cast<std::size_t>(std::find(tags.begin(), tags.end(), tag_id[k]) - tags.begin());
      if (t > 0 && t <= extra) columns[t - 1] += row;
    }
  }
  const Eigen::Index unknowns = 4 + static_cast<Eigen::Index>(extra);
  Eigen::MatrixXd information = Eigen::MatrixXd::Zero(unknowns, unknowns);
  information.topLeftCorner<4, 4>() = core;
  for (std::size_t t = 0; t < extra; ++t) {
    const Eigen::Index c = 4 + static_cast<Eigen::Index>(t);
    information.block<4, 1>(0, c) = columns[t];
    information.block<1, 4>(c, 0) = columns[t].transpose();
    information(c, c) = columns[t](3);  // the tag's count: its rows' bias entries
  }
  return information;
}

}  // namespace anchorbench::estimator
