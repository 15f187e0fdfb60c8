#include "anchorbench/estimator/height_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

#include "anchorbench/estimator/tag_biases.hpp"

namespace anchorbench::estimator {
namespace {

constexpr double kOnPlaneM = 1e-3;        // an estimate this close to the plane is its own mirror
constexpr double kMadToSigma = 1.4826;    // sigma of Gaussian noise from its median absolute deviation
constexpr double kMinSigmaM = 1e-6;       // noiseless data: a floor, so the evidence stays finite

// The median of `values`, which it reorders (the evidence below passes buffers it no longer needs:
// every nth_element sees the same values in the same order as a copy would, so the sums are the
// same to the bit).
double MedianInPlace(std::vector<double>& values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// d_k - |p_k - p_A| - gamma for every sample: the negative of Eq. (11)'s RangeResidual
// (range_residual.hpp), as measured minus predicted. Written as the negation, (|p_k - p_A| + gamma)
// - d_k, its rounding moves a borderline mirror decision and changes committed tables (flat_path,
// cone_approach), so it stays in this form until results may move.
std::vector<double> Residuals(std::span<const Eigen::Vector3d> p, std::span<const double> d, const Eigen::Vector3d& p_anchor,
                              double bias_m) {
  std::vector<double> r(p.size());
  for (std::size_t k = 0; k < p.size(); ++k) r[k] = d[k] - (p[k] - p_anchor).norm() - bias_m;
  return r;
}

// FitEvidence of two fits' residuals, both consumed: one scratch buffer besides them (the medians
// of a and of its deviations), so a test over N samples allocates three arrays, not seven.
double EvidenceOfResiduals(std::vector<double> a, std::vector<double> b, double trim_fraction, double explained_squares,
                           double* explained = nullptr) {
  std::vector<double> scratch = a;
  const double a_median = MedianInPlace(scratch);
  for (std::size_t k = 0; k < a.size(); ++k) scratch[k] = std::abs(a[k] - a_median);
  const double sigma_m = std::max(kMadToSigma * MedianInPlace(scratch), kMinSigmaM);
  if (explained) *explained = explained_squares / (sigma_m * sigma_m);
  return (TrimmedSquaresInPlace(b, trim_fraction) - TrimmedSquaresInPlace(a, trim_fraction) - explained_squares) /
         (sigma_m * sigma_m);
}

// Each tag's residuals less their median (a handful of tags at most; none: nothing to center).
void CenterEachTag(std::span<const int> tag_id, std::vector<double>& residuals) {
  std::vector<double> own;
  for (const int tag : TagsInOrder(tag_id)) {
    own.clear();
    for (std::size_t k = 0; k < residuals.size(); ++k) {
      if (tag_id[k] == tag) own.push_back(residuals[k]);
    }
    const double median = MedianInPlace(own);
    for (std::size_t k = 0; k < residuals.size(); ++k) {
      if (tag_id[k] == tag) residuals[k] -= median;
    }
  }
}

}  // namespace

double TrimmedSquaresInPlace(std::vector<double>& residuals, double trim_fraction) {
  if (residuals.empty()) return 0.0;
  for (double& r : residuals) r = r * r;
  const auto kept = static_cast<std::size_t>(std::ceil((1.0 - trim_fraction) * static_cast<double>(residuals.size())));
  std::nth_element(residuals.begin(), residuals.begin() + static_cast<std::ptrdiff_t>(kept - 1), residuals.end());
  double sum = 0.0;
  for (std::size_t k = 0; k < kept; ++k) sum += residuals[k];
  return sum;
}

bool HeightCheckOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* message) {
    if (why) *why = message;
    return false;
  };
  if (!(min_evidence >= 0.0 && min_evidence <= 1e6)) return fail("min_evidence must be in [0, 1e6]");
  if (!(trim_fraction >= 0.0 && trim_fraction <= 0.5)) return fail("trim_fraction must be in [0, 0.5]");
  if (!(min_separation >= 0.0 && min_separation <= 1e6)) return fail("min_separation must be in [0, 1e6]");
  return true;
}

Mirror MirrorOf(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                const SolveResult& estimate, double trim_fraction) {
  Mirror mirror;
  const std::size_t n = p_world_tag.size();
  if (n < 5) return mirror;
  // The plane of the tag positions: through their centroid, normal to their least spread.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : p_world_tag) centroid += p;
  centroid /= static_cast<double>(n);
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : p_world_tag) scatter.noalias() += (p - centroid) * (p - centroid).transpose();
  mirror.normal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvectors().col(0);
  if (mirror.normal.z() < 0.0) mirror.normal = -mirror.normal;
  mirror.height_m = (estimate.p_world_anchor - centroid).dot(mirror.normal);
  if (std::abs(mirror.height_m) < kOnPlaneM) return mirror;
  mirror.exists = true;
  mirror.p_world_mirror = estimate.p_world_anchor - 2.0 * mirror.height_m * mirror.normal;

  // The mirror's residuals with its bias refit, as the median of those without: d - |p - m| - gamma
  // computed as (d - |p - m|) - gamma, the same rounding as Residuals at that bias.
  std::vector<double> mirror_residuals = Residuals(p_world_tag, range_m, mirror.p_world_mirror, 0.0);
  std::vector<double> scratch = mirror_residuals;
  mirror.bias_mirror_m = MedianInPlace(scratch);
  for (double& r : mirror_residuals) r -= mirror.bias_mirror_m;
  mirror.evidence = EvidenceOfResiduals(Residuals(p_world_tag, range_m, estimate.p_world_anchor, estimate.bias_m),
                                        std::move(mirror_residuals), trim_fraction, 0.0);
  return mirror;
}

double FitEvidenceOwnOffsets(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                             std::span<const int> tag_id, const Eigen::Vector3d& p_a, double bias_a_m,
                             const Eigen::Vector3d& p_b, double bias_b_m, double trim_fraction,
                             double explained_squares, double* explained) {
  std::vector<double> a = Residuals(p_world_tag, range_m, p_a, bias_a_m);
  std::vector<double> b = Residuals(p_world_tag, range_m, p_b, bias_b_m);
  CenterEachTag(tag_id, a);
  CenterEachTag(tag_id, b);
  return EvidenceOfResiduals(std::move(a), std::move(b), trim_fraction, explained_squares, explained);
}

double FitEvidence(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                   const Eigen::Vector3d& p_a, double bias_a_m, const Eigen::Vector3d& p_b, double bias_b_m,
                   double trim_fraction, double explained_squares, double* explained) {
  return FitEvidenceOwnOffsets(p_world_tag, range_m, {}, p_a, bias_a_m, p_b, bias_b_m, trim_fraction,
                               explained_squares, explained);
}

double Separation(std::span<const Eigen::Vector3d> p_world_tag, const Eigen::Vector3d& p_a, double bias_a_m,
                  const Eigen::Vector3d& p_b, double bias_b_m, double residual_scale_m) {
  double sum = 0.0;
  for (const Eigen::Vector3d& p : p_world_tag) {
    const double difference = (p - p_a).norm() + bias_a_m - (p - p_b).norm() - bias_b_m;
    sum += difference * difference;
  }
  const double scale_m = std::max(residual_scale_m, 1e-3);
  return sum / (scale_m * scale_m);
}

double MirrorEvidence(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                      const SolveResult& estimate, double trim_fraction) {
  return MirrorOf(p_world_tag, range_m, estimate, trim_fraction).evidence;
}

SolveResult HeightCheckedSolver::Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const {
  using Side = HeightCheckOptions::Side;
  SolveResult result = inner().Solve(p_world_tag, range_m);
  if (!Succeeded(result.status)) return result;
  Mirror mirror = MirrorOf(p_world_tag, range_m, result, options_.trim_fraction);
  // The solver's height prior, if it has one: the prior's chi-square of the mirror minus the
  // estimate's joins the evidence.
  const std::optional<HeightPrior> prior = height_prior();
  if (mirror.exists && prior) mirror.evidence += prior->Chi2(mirror.p_world_mirror.z()) - prior->Chi2(result.p_world_anchor.z());
  if (!mirror.exists) return result;
  // The data (and a height prior, which alone separates the two) decide.
  const auto separation = [&] {
    if (prior) return std::numeric_limits<double>::infinity();
    double squares = 0.0;
    for (const double r : Residuals(p_world_tag, range_m, result.p_world_anchor, result.bias_m)) squares += r * r;
    const double scale_m = std::sqrt(squares / static_cast<double>(std::max<std::size_t>(range_m.size(), 5) - 4));
    return Separation(p_world_tag, result.p_world_anchor, result.bias_m, mirror.p_world_mirror, mirror.bias_mirror_m,
                      scale_m);
  };
  const FitComparison comparison{mirror.evidence, options_.min_evidence, separation(), options_.min_separation,
                                 range_m.size()};
  if (comparison.evidence >= comparison.evidence_needed && comparison.separated()) return result;
  // Ambiguous. Without a usable side prior, say so, with both tests' numbers.
  constexpr double kMinNormalZ = 0.5;  // cos(60 deg): a steeper plane has no above and below
  if (options_.side == Side::kAny || mirror.normal.z() < kMinNormalZ) {
    result.status = SolveStatus::kHeightUnobservable;
    result.mirror_refusal = comparison;
    return result;
  }
  const bool above = mirror.height_m > 0.0;
  if (above == (options_.side == Side::kAbove)) return result;
  // The prior's side is the mirror's: reflect the estimate, its bias refit, its covariance.
  const Eigen::Matrix3d reflection = Eigen::Matrix3d::Identity() - 2.0 * mirror.normal * mirror.normal.transpose();
  Eigen::Matrix4d to_mirror = Eigen::Matrix4d::Identity();
  to_mirror.topLeftCorner<3, 3>() = reflection;
  result.p_world_anchor = mirror.p_world_mirror;
  result.bias_m = mirror.bias_mirror_m;
  result.covariance = to_mirror * result.covariance * to_mirror.transpose();
  return result;
}

}  // namespace anchorbench::estimator
