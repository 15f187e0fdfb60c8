#include "anchorbench/estimator/height_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Eigenvalues>

namespace anchorbench::estimator {
namespace {

constexpr double kOnPlaneM = 1e-3;        // an estimate this close to the plane is its own mirror
constexpr double kMadToSigma = 1.4826;    // sigma of Gaussian noise from its median absolute deviation
constexpr double kMinSigmaM = 1e-6;       // noiseless data: a floor, so the evidence stays finite

double Median(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// The sum of squares of the smallest (1 - trim) share of |r|.
double TrimmedSquares(std::vector<double> residuals, double trim_fraction) {
  for (double& r : residuals) r = r * r;
  const auto kept = static_cast<std::size_t>(std::ceil((1.0 - trim_fraction) * static_cast<double>(residuals.size())));
  std::nth_element(residuals.begin(), residuals.begin() + static_cast<std::ptrdiff_t>(kept - 1), residuals.end());
  double sum = 0.0;
  for (std::size_t k = 0; k < kept; ++k) sum += residuals[k];
  return sum;
}

// d_k - |p_k - p_A| - gamma for every sample.
std::vector<double> Residuals(std::span<const Eigen::Vector3d> p, std::span<const double> d, const Eigen::Vector3d& p_anchor,
                              double bias_m) {
  std::vector<double> r(p.size());
  for (std::size_t k = 0; k < p.size(); ++k) r[k] = d[k] - (p[k] - p_anchor).norm() - bias_m;
  return r;
}

}  // namespace

bool HeightCheckOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* message) {
    if (why) *why = message;
    return false;
  };
  if (!(min_evidence >= 0.0) || !std::isfinite(min_evidence)) return fail("min_evidence must be >= 0");
  if (!(trim_fraction >= 0.0 && trim_fraction <= 0.5)) return fail("trim_fraction must be in [0, 0.5]");
  return true;
}

double MirrorEvidence(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                      const SolveResult& estimate, double trim_fraction) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const std::size_t n = p_world_tag.size();
  if (n < 5) return kInf;
  // The plane of the tag positions: through their centroid, normal to their least spread.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : p_world_tag) centroid += p;
  centroid /= static_cast<double>(n);
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : p_world_tag) scatter.noalias() += (p - centroid) * (p - centroid).transpose();
  const Eigen::Vector3d normal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvectors().col(0);
  const double height_m = (estimate.p_world_anchor - centroid).dot(normal);
  if (std::abs(height_m) < kOnPlaneM) return kInf;
  const Eigen::Vector3d p_mirror = estimate.p_world_anchor - 2.0 * height_m * normal;

  const std::vector<double> own = Residuals(p_world_tag, range_m, estimate.p_world_anchor, estimate.bias_m);
  std::vector<double> mirror = Residuals(p_world_tag, range_m, p_mirror, 0.0);
  const double bias_mirror_m = Median(mirror);
  for (double& r : mirror) r -= bias_mirror_m;

  std::vector<double> deviations(own.size());
  const double own_median = Median(own);
  for (std::size_t k = 0; k < own.size(); ++k) deviations[k] = std::abs(own[k] - own_median);
  const double sigma_m = std::max(kMadToSigma * Median(deviations), kMinSigmaM);
  return (TrimmedSquares(mirror, trim_fraction) - TrimmedSquares(own, trim_fraction)) / (sigma_m * sigma_m);
}

SolveResult HeightCheckedSolver::Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const {
  SolveResult result = inner_->Solve(p_world_tag, range_m);
  if (Succeeded(result.status) &&
      MirrorEvidence(p_world_tag, range_m, result, options_.trim_fraction) < options_.min_evidence) {
    result.status = SolveStatus::kHeightUnobservable;
  }
  return result;
}

}  // namespace anchorbench::estimator
