#pragma once

#include <memory>
#include <span>
#include <string>

#include <Eigen/Core>

#include "anchorbench/estimator/solver.hpp"

namespace anchorbench::estimator {

// The mirror ambiguity of a flat path (ours, docs/method.md): with every tag position on one
// plane, the anchor reflected through that plane has the same distance to every tag, so it fits
// the ranges exactly as well, and no DOP can tell the two apart. A nearly flat path leaves the
// mirror almost as good. The check reflects an estimate through the plane fitted to the tag
// positions, refits the bias there (the median of the range residuals), and compares the two
// fits. The evidence is the trimmed sum of squared residuals of the mirror minus the estimate's,
// in units of the estimate's robust residual variance (1.4826 MAD)^2: a log-likelihood ratio
// (x2) under Gaussian noise, robust to the outliers the trimming drops.
struct HeightCheckOptions {
  bool enabled = false;       // off: the paper's estimator, which has no such check
  double min_evidence = 9.21; // below this the mirror is within a likelihood ratio of 100: ambiguous
  double trim_fraction = 0.1; // the largest residuals of each fit left out of its sum

  bool IsValid(std::string* why) const;
};

// The evidence against the mirror of `estimate` (see above); +infinity when there is no mirror to
// fear: the estimate on the tags' plane (within 1 mm), or fewer than 5 samples.
double MirrorEvidence(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                      const SolveResult& estimate, double trim_fraction);

// A solver whose successful estimates must beat their mirror: otherwise the status is
// kHeightUnobservable (not a success: an online initializer retries with more data, the fixed
// window reports it).
class HeightCheckedSolver : public Solver {
 public:
  HeightCheckedSolver(std::shared_ptr<const Solver> inner, const HeightCheckOptions& options)
      : inner_(std::move(inner)), options_(options) {}
  SolveResult Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const override;

 private:
  std::shared_ptr<const Solver> inner_;
  HeightCheckOptions options_;
};

}  // namespace anchorbench::estimator
