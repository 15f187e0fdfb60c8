#pragma once

#include <span>
#include <string>
#include <vector>

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
// solver's solve. `offsets_m` gets each tag's delta, in the order `tag_id` first shows them.
// The covariance gains each offset's uncertainty, sigma^2 / n_t, through the rows of its tag.
SolveResult SolveWithTagBiases(const Solver& solver, std::span<const Eigen::Vector3d> p_world_tag,
                               std::span<const double> range_m, std::span<const int> tag_id,
                               const TagBiasOptions& options, std::vector<double>* offsets_m = nullptr);

}  // namespace anchorbench::estimator
