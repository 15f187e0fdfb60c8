#include "anchorbench/estimator/ls_solver.hpp"

#include <cmath>

#include <Eigen/Cholesky>

#include "numerics.hpp"

namespace anchorbench::estimator {
namespace {

// One double-difference row k against the pivot j, positions relative to p_j.
struct Row {
  Eigen::Vector4d a;
  double b;
  double weight;
};

class RowBuilder {
 public:
  RowBuilder(std::span<const Eigen::Vector3d> p, std::span<const double> d, const LsOptions& options)
      : p_(p), d_(d), options_(options),
        var_d_(options.sigma_range_m * options.sigma_range_m),
        var_p_(options.sigma_position_m * options.sigma_position_m) {
    for (std::size_t k = 0; k < d.size(); ++k) {
      const double score = PivotScore(k);
      if (k == 0 || score < pivot_score_) {
        pivot_ = k;
        pivot_score_ = score;
      }
    }
  }

  std::size_t pivot() const { return pivot_; }

  Row operator()(std::size_t k) const {
    const Eigen::Vector3d dp = p_[k] - p_[pivot_];
    const double d_k = d_[k];
    const double d_j = d_[pivot_];
    Row row;
    row.a << -dp, d_k - d_j;                                       // Eq. (9)
    row.b = 0.5 * ((d_k * d_k - d_j * d_j) - dp.squaredNorm());  // Eq. (10), origin at p_j
    // UVIO weighting: inverse variance of the row, pivot variance included.
    row.weight = options_.pivot == LsPivot::kShortestRange ? 1.0 : 1.0 / (PivotScore(k) + pivot_score_);
    return row;
  }

 private:
  double PivotScore(std::size_t k) const {
    return options_.pivot == LsPivot::kShortestRange ? d_[k]
                                                     : d_[k] * d_[k] * var_d_ + var_p_ * p_[k].squaredNorm();
  }

  std::span<const Eigen::Vector3d> p_;
  std::span<const double> d_;
  const LsOptions& options_;
  double var_d_;
  double var_p_;
  std::size_t pivot_ = 0;
  double pivot_score_ = 0.0;
};

}  // namespace

std::string_view ToString(LsPivot pivot) {
  return pivot == LsPivot::kShortestRange ? "shortest_range" : "minimum_variance";
}

bool ParseLsPivot(std::string_view name, LsPivot* pivot) {
  if (name == "shortest_range") *pivot = LsPivot::kShortestRange;
  else if (name == "minimum_variance") *pivot = LsPivot::kMinimumVariance;
  else return false;
  return true;
}

bool LsOptions::IsValid(std::string* why) const {
  if (!(sigma_range_m > 0.0) || !std::isfinite(sigma_range_m)) {
    if (why) *why = "sigma_range_m must be > 0";
    return false;
  }
  if (!(sigma_position_m >= 0.0) || !std::isfinite(sigma_position_m)) {
    if (why) *why = "sigma_position_m must be >= 0";
    return false;
  }
  return true;
}

SolveResult SolveDoubleDifferenceLs(std::span<const Eigen::Vector3d> p_world_tag,
                                    std::span<const double> range_m, const LsOptions& options) {
  SolveResult result;
  if (range_m.size() < kMinSamplesLs || p_world_tag.size() != range_m.size()) {
    result.status = SolveStatus::kTooFewSamples;
    return result;
  }
  const RowBuilder rows(p_world_tag, range_m, options);
  const std::size_t j = rows.pivot();

  Eigen::Matrix4d normal = Eigen::Matrix4d::Zero();
  Eigen::Vector4d rhs = Eigen::Vector4d::Zero();
  for (std::size_t k = 0; k < range_m.size(); ++k) {
    if (k == j) continue;
    const Row row = rows(k);
    normal.noalias() += row.weight * row.a * row.a.transpose();
    rhs += row.weight * row.b * row.a;
  }

  if (!normal.allFinite() || !rhs.allFinite()) {
    result.status = SolveStatus::kNumericalFailure;
    return result;
  }
  Eigen::Matrix4d normal_inverse;
  if (!internal::InvertNormalMatrix(normal, &normal_inverse)) {
    result.status = SolveStatus::kDegenerateGeometry;  // e.g. collinear tag positions
    return result;
  }
  const Eigen::Vector4d x = normal_inverse * rhs;

  // Covariance s^2 (A^T W A)^-1, s^2 the weighted residual variance of the linear system.
  double weighted_squares = 0.0;
  for (std::size_t k = 0; k < range_m.size(); ++k) {
    if (k == j) continue;
    const Row row = rows(k);
    const double residual = row.a.dot(x) - row.b;
    weighted_squares += row.weight * residual * residual;
  }
  const double dof = static_cast<double>(range_m.size()) - 1.0 - 4.0;
  result.p_world_anchor = p_world_tag[j] + x.head<3>();
  result.bias_m = x(3);
  result.covariance = (weighted_squares / dof) * normal_inverse;
  result.status = SolveStatus::kConverged;
  result.iterations = 1;
  return result;
}

SolveResult SolveSingleDifferenceLs(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) {
  SolveResult result;
  const std::size_t n = range_m.size();
  if (n < kMinSamplesLs || p_world_tag.size() != n) {
    result.status = SolveStatus::kTooFewSamples;
    return result;
  }
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : p_world_tag) origin += p / static_cast<double>(n);
  using Vector5 = Eigen::Matrix<double, 5, 1>;
  Eigen::Matrix<double, 5, 5> normal = Eigen::Matrix<double, 5, 5>::Zero();
  Vector5 rhs = Vector5::Zero();
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d p = p_world_tag[k] - origin;
    Vector5 a;
    a << -2.0 * p, 2.0 * range_m[k], 1.0;
    const double b = range_m[k] * range_m[k] - p.squaredNorm();
    normal.noalias() += a * a.transpose();
    rhs += b * a;
  }
  const Eigen::LDLT<Eigen::Matrix<double, 5, 5>> ldlt(normal);
  if (!normal.allFinite() || !internal::IsWellConditioned(ldlt)) {
    result.status = SolveStatus::kDegenerateGeometry;
    return result;
  }
  const Vector5 x = ldlt.solve(rhs);
  if (!x.allFinite()) {
    result.status = SolveStatus::kNumericalFailure;
    return result;
  }
  result.p_world_anchor = origin + x.head<3>();
  result.bias_m = x(3);
  result.status = SolveStatus::kConverged;
  result.iterations = 1;
  return result;
}

}  // namespace anchorbench::estimator
