#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/estimator/enum_names.hpp"
#include "anchorbench/estimator/height_prior.hpp"
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
//
// A side prior resolves the ambiguity where the user knows it (anchors on the ceiling above a
// ground robot): with `side` above or below, an ambiguous estimate on the other side of the tags'
// plane is replaced by its mirror (bias refit there, covariance reflected), and an ambiguous one
// on the prior's side is accepted. Where the data decide (evidence >= min_evidence) they win over
// the prior. "Above" is the side the plane's normal points to with a positive z; a plane within
// 60 degrees of vertical has no above, and the prior is not used.
struct HeightCheckOptions {
  enum class Side { kAny, kAbove, kBelow };
  bool enabled = true;        // on for real logs (ours); the paper's estimator has no such check (configs/paper.yaml)
  double min_evidence = 9.21; // below this the mirror is within a likelihood ratio of 100: ambiguous
  // ...and the two fits must predict ranges that differ by this much, lambda = sum (difference /
  // sigma)^2 (ours): the likelihood ratio's own spread grows like 2 sqrt(lambda), more with noise in
  // the tag positions (on the flat floor 1 cm of it swung a lambda ~10 pair from -15 to +28), so
  // only a separation no swing crosses counts as evidence.
  double min_separation = 100.0;
  double trim_fraction = 0.1; // the largest residuals of each fit left out of its sum
  Side side = Side::kAny;     // the anchor's side of the tags' plane, if known

  bool IsValid(std::string* why) const;
};
inline constexpr EnumNames<HeightCheckOptions::Side, 3> kSideNames({
    {HeightCheckOptions::Side::kAny, "any"}, {HeightCheckOptions::Side::kAbove, "above"},
    {HeightCheckOptions::Side::kBelow, "below"}});
inline std::string_view ToString(HeightCheckOptions::Side value) { return kSideNames.Name(value); }
inline bool ParseSide(std::string_view name, HeightCheckOptions::Side* value) { return kSideNames.Parse(name, value); }

// An estimate's mirror through the plane of the tag positions.
struct Mirror {
  bool exists = false;  // false: fewer than 5 samples, or the estimate within 1 mm of the plane
  double evidence = std::numeric_limits<double>::infinity();  // against the mirror (see above)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();          // of the plane, z component >= 0
  double height_m = 0.0;                                      // of the estimate along the normal
  Eigen::Vector3d p_world_mirror = Eigen::Vector3d::Zero();
  double bias_mirror_m = 0.0;
};
Mirror MirrorOf(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                const SolveResult& estimate, double trim_fraction);

// The sum of squares of the smallest (1 - trim_fraction) share of |r|, as the evidence trims them;
// squares and reorders `residuals` (a buffer the caller no longer needs).
double TrimmedSquaresInPlace(std::vector<double>& residuals, double trim_fraction);

// The evidence for fit `a` over fit `b` of the same data: the trimmed sum of squared residuals of
// b minus a's, over a's robust residual variance (1.4826 MAD)^2 (negative: b fits better).
// `explained_squares` (m^2) is taken off the difference of squares first: what a range error
// outside the noise model could account for (the certificate's model error); `explained`, if
// given, receives it in the evidence's units.
double FitEvidence(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                   const Eigen::Vector3d& p_a, double bias_a_m, const Eigen::Vector3d& p_b, double bias_b_m,
                   double trim_fraction, double explained_squares = 0.0, double* explained = nullptr);

// FitEvidence where the samples come from several tags whose range offsets are unknown (tag_id per
// sample, the ranges corrected by one fit's estimate of them): each fit's residuals less each
// tag's median of them, so that each fit is judged with the offsets that suit it best. Judged with
// another fit's offsets, an alternative carries their error: on a three-tag rig whose links differ
// by 0.2 m, the true anchor fitted worse than an estimate metres off with that estimate's offsets,
// and better with its own. An empty tag_id centers nothing: FitEvidence.
double FitEvidenceOwnOffsets(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                             std::span<const int> tag_id, const Eigen::Vector3d& p_a, double bias_a_m,
                             const Eigen::Vector3d& p_b, double bias_b_m, double trim_fraction,
                             double explained_squares = 0.0, double* explained = nullptr);

// lambda = sum over samples of the squared difference of the ranges two fits predict, in units of
// `residual_scale_m` (floored at 1 mm).
double Separation(std::span<const Eigen::Vector3d> p_world_tag, const Eigen::Vector3d& p_a, double bias_a_m,
                  const Eigen::Vector3d& p_b, double bias_b_m, double residual_scale_m);

// The evidence against the mirror of `estimate`; +infinity where there is none.
double MirrorEvidence(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                      const SolveResult& estimate, double trim_fraction);

// A solver whose successful estimates must beat their mirror: otherwise the status is
// kHeightUnobservable (not a success: an online initializer retries with more data, the fixed
// window reports it).
class HeightCheckedSolver : public SolverDecorator {
 public:
  HeightCheckedSolver(std::shared_ptr<const Solver> inner, const HeightCheckOptions& options)
      : SolverDecorator(std::move(inner)), options_(options) {}
  SolveResult Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const override;

 private:
  HeightCheckOptions options_;
};

}  // namespace anchorbench::estimator
