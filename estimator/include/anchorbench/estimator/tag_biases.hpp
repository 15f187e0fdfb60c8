#pragma once

#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/estimator/solver.hpp"

namespace anchorbench::estimator {

// One range bias per tag (ours): a multi-tag robot's tags range to an anchor with offsets of their
// own (0.1-0.3 m on a public three-tag recording), which one bias gamma cannot absorb. With it, the
// ranges are d_k = |p_k - p_A| + gamma + delta_{tag(k)} + eta, delta = 0 for the first tag seen.
struct TagBiasOptions {
  bool estimate = true;  // with two or more tags in the data; the paper has one bias (configs/paper.yaml)
  int iterations = 4;    // of the alternation below

  bool IsValid(std::string* why) const;
};

// The solve with each tag's offset: alternately the solver on the ranges less the offsets, and each
// offset as the mean residual of its tag's ranges against the first tag's. With one tag it is the
// solver's solve. `offsets_m` gets each tag's delta, in the order `tag_id` first shows them, and
// `corrected_m` the ranges less their tag's delta (what the solve fitted; the ranges with one tag).
// The covariance is the (p_A, gamma) block of the joint one (TagInformation); an offset the data
// cannot tell from the position makes the solve kDegenerateGeometry.
SolveResult SolveWithTagBiases(const Solver& solver, std::span<const Eigen::Vector3d> p_world_tag,
                               std::span<const double> range_m, std::span<const int> tag_id,
                               const TagBiasOptions& options, std::vector<double>* offsets_m = nullptr,
                               std::vector<double>* corrected_m = nullptr);

// The distinct tags of `tag_id`, in the order they first appear.
std::vector<int> TagsInOrder(std::span<const int> tag_id);
// The tags whose offsets are among a solve's unknowns: with `estimate` and a tag for each of the
// `samples`, TagsInOrder; else {0}, one bias for all.
std::vector<int> OffsetTags(std::span<const int> tag_id, std::size_t samples, bool estimate);

// The information of (p_A, gamma, delta_2..delta_T) at an anchor position: rows [-u_k, 1, e_tag(k)]
// (the first of `tags` has no offset of its own). O(N T^2).
Eigen::MatrixXd TagInformation(std::span<const Eigen::Vector3d> p_world_tag, std::span<const int> tag_id,
                               const std::vector<int>& tags, const Eigen::Vector3d& p_world_anchor);

}  // namespace anchorbench::estimator
