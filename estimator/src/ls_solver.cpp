#include "anchorbench/estimator/ls_solver.hpp"

#include <cmath>
#include <optional>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "numerics.hpp"

namespace anchorbench::estimator {
namespace {

// One double-difference row k against the pivot j, positions relative to p_j.
struct DifferenceRow {
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

  DifferenceRow operator()(std::size_t k) const {
    const Eigen::Vector3d dp = p_[k] - p_[pivot_];
    const double d_k = d_[k];
    const double d_j = d_[pivot_];
    DifferenceRow row;
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
  LsOptions options_;  // a copy: a caller may pass a temporary
  double var_d_;
  double var_p_;
  std::size_t pivot_ = 0;
  double pivot_score_ = 0.0;
};

}  // namespace

bool LsOptions::IsValid(std::string* why) const {
  if (!(sigma_range_m > 0.0 && sigma_range_m <= 100.0)) {
    if (why) *why = "sigma_range_m must be in (0, 100]";
    return false;
  }
  if (!(sigma_position_m >= 0.0 && sigma_position_m <= 100.0)) {
    if (why) *why = "sigma_position_m must be in [0, 100]";
    return false;
  }
  return true;
}

namespace {

// sum w (a^T x - b)^2 over the rows.
double WeightedSquares(const RowBuilder& rows, std::size_t n, const Eigen::Vector4d& x) {
  double weighted_squares = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    if (k == rows.pivot()) continue;
    const DifferenceRow row = rows(k);
    const double residual = row.a.dot(x) - row.b;
    weighted_squares += row.weight * residual * residual;
  }
  return weighted_squares;
}

// The rows' residual variance with the anchor's height held at the prior (x(2) = x_z, positions
// relative to the pivot): the scale that puts the prior, in metres, beside rows in m^2. False
// when x-y and the bias are not determined even with the height known.
bool RowVarianceAtHeight(const RowBuilder& rows, std::size_t n, const Eigen::Matrix4d& normal,
                         const Eigen::Vector4d& rhs, double x_z, double* variance) {
  constexpr int kFree[3] = {0, 1, 3};  // x, y, bias
  Eigen::Matrix3d reduced;
  Eigen::Vector3d reduced_rhs;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) reduced(i, j) = normal(kFree[i], kFree[j]);
    reduced_rhs(i) = rhs(kFree[i]) - normal(kFree[i], 2) * x_z;
  }
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(reduced);
  if (!internal::IsWellConditioned(ldlt)) return false;
  const Eigen::Vector3d free = ldlt.solve(reduced_rhs);
  const Eigen::Vector4d x(free(0), free(1), x_z, free(2));
  *variance = WeightedSquares(rows, n, x) / (static_cast<double>(n) - 1.0 - 3.0);
  return std::isfinite(*variance);
}

// The covariance of x from the range noise, propagated through the rows (ours). A row's error is
// (d_k - gamma) e_k - (d_j - gamma) e_j to first order: the pivot's noise is in every row, so the
// rows are correlated, which s^2 (A^T W A)^-1 leaves out (ls_double was 3.5x over-confident on
// white noise). With N = A^T W A:
//   Cov = N^-1 [ sum w_k^2 (d_k - gamma)^2 a_k a_k^T + (d_j - gamma)^2 (sum w_k a_k)(sum w_k a_k)^T ] N^-1 s_r^2
// (+ the prior row's w_p^2 sigma_p^2 e_z e_z^T in the brackets), s_r^2 the range residuals'
// variance at the estimate.
Eigen::Matrix4d PropagatedCovariance(const RowBuilder& rows, std::span<const Eigen::Vector3d> p,
                                     std::span<const double> d, const Eigen::Matrix4d& normal_inverse,
                                     const Eigen::Vector4d& x, double prior_weight,
                                     const std::optional<HeightPrior>& prior) {
  const std::size_t n = d.size(), j = rows.pivot();
  const double gamma = x(3);
  const Eigen::Vector3d p_anchor = p[j] + x.head<3>();
  double squares = 0.0;
  Eigen::Matrix4d meat = Eigen::Matrix4d::Zero();
  Eigen::Vector4d pivot_column = Eigen::Vector4d::Zero();
  for (std::size_t k = 0; k < n; ++k) {
    const double r = (p[k] - p_anchor).norm() + gamma - d[k];
    squares += r * r;
    if (k == j) continue;
    const DifferenceRow row = rows(k);
    const double scale = row.weight * (d[k] - gamma);
    meat.noalias() += scale * scale * row.a * row.a.transpose();
    pivot_column += row.weight * row.a;
  }
  const double pivot_scale = d[j] - gamma;
  meat.noalias() += pivot_scale * pivot_scale * pivot_column * pivot_column.transpose();
  const double variance = squares / (static_cast<double>(n) - 4.0);
  meat *= variance;
  if (prior) meat(2, 2) += prior_weight * prior_weight * prior->sigma_m * prior->sigma_m;
  return normal_inverse * meat * normal_inverse;
}

// Total least squares: the x minimizing ||A x - b||^2 / (1 + ||x||^2), i.e. v = [x; -1] along the
// eigenvector of the smallest eigenvalue of the Gram matrix of [A b]. False when that eigenvector
// has no b component (no solution of this form).
bool TotalLeastSquares(const Eigen::Matrix4d& normal, const Eigen::Vector4d& rhs, double b_squares,
                       Eigen::Vector4d* x) {
  using Matrix5d = Eigen::Matrix<double, 5, 5>;
  Matrix5d gram;
  gram.topLeftCorner<4, 4>() = normal;
  gram.topRightCorner<4, 1>() = rhs;
  gram.bottomLeftCorner<1, 4>() = rhs.transpose();
  gram(4, 4) = b_squares;
  const Eigen::SelfAdjointEigenSolver<Matrix5d> eigen(gram);
  if (eigen.info() != Eigen::Success) return false;
  const Eigen::Matrix<double, 5, 1> v = eigen.eigenvectors().col(0);  // eigenvalues ascending
  if (!(std::abs(v(4)) > 1e-12)) return false;
  *x = -v.head<4>() / v(4);
  return x->allFinite();
}

// The rows' normal equations sum w a a^T x = sum w b a, in one O(N) pass, and sum w b^2 (for total
// least squares).
struct NormalSums {
  Eigen::Matrix4d normal = Eigen::Matrix4d::Zero();
  Eigen::Vector4d rhs = Eigen::Vector4d::Zero();
  double b_squares = 0.0;
};

NormalSums NormalEquations(const RowBuilder& rows, std::size_t n) {
  NormalSums sums;
  for (std::size_t k = 0; k < n; ++k) {
    if (k == rows.pivot()) continue;
    const DifferenceRow row = rows(k);
    sums.normal.noalias() += row.weight * row.a * row.a.transpose();
    sums.rhs += row.weight * row.b * row.a;
    sums.b_squares += row.weight * row.b * row.b;
  }
  return sums;
}

}  // namespace

std::optional<Eigen::Vector3d> SolveBiasFreeLs(std::span<const Eigen::Vector3d> p_world_tag,
                                               std::span<const double> range_m) {
  const std::size_t n = range_m.size();
  if (n < kMinSamplesLs || p_world_tag.size() != n) return std::nullopt;
  const RowBuilder rows(p_world_tag, range_m, LsOptions{});
  // gamma = 0 drops Eq. (9)'s last column: the position block of the same normal equations.
  const NormalSums sums = NormalEquations(rows, n);
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(sums.normal.topLeftCorner<3, 3>());
  if (!sums.normal.allFinite() || !sums.rhs.allFinite() || !internal::IsWellConditioned(ldlt)) return std::nullopt;
  const Eigen::Vector3d x = ldlt.solve(sums.rhs.head<3>());
  if (!x.allFinite()) return std::nullopt;
  return p_world_tag[rows.pivot()] + x;
}

SolveResult SolveDoubleDifferenceLs(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                                    const LsOptions& options, const std::optional<HeightPrior>& height_prior) {
  SolveResult result;
  const std::size_t n = range_m.size();
  if (n < kMinSamplesLs || p_world_tag.size() != n) {
    result.status = SolveStatus::kTooFewSamples;
    return result;
  }
  const RowBuilder rows(p_world_tag, range_m, options);
  const std::size_t j = rows.pivot();
  auto [normal, rhs, b_squares] = NormalEquations(rows, n);
  if (!normal.allFinite() || !rhs.allFinite()) {
    result.status = SolveStatus::kNumericalFailure;
    return result;
  }
  double prior_weight = 0.0;
  double prior_x_z = 0.0;
  if (height_prior) {
    // The prior as one more row [0 0 1 0] x = z - z_j, weighted s^2 / sigma^2 against the rows.
    prior_x_z = height_prior->z_world_m - p_world_tag[j].z();
    double row_variance = 0.0;
    if (!RowVarianceAtHeight(rows, n, normal, rhs, prior_x_z, &row_variance)) {
      result.status = SolveStatus::kDegenerateGeometry;
      return result;
    }
    prior_weight = row_variance / (height_prior->sigma_m * height_prior->sigma_m);
    normal(2, 2) += prior_weight;
    rhs(2) += prior_weight * prior_x_z;
    b_squares += prior_weight * prior_x_z * prior_x_z;
  }
  Eigen::Matrix4d normal_inverse;
  if (!internal::InvertNormalMatrix(normal, &normal_inverse)) {
    result.status = SolveStatus::kDegenerateGeometry;  // e.g. collinear tag positions
    return result;
  }
  Eigen::Vector4d x = normal_inverse * rhs;
  if (options.method == LsMethod::kTotal && !TotalLeastSquares(normal, rhs, b_squares, &x)) {
    result.status = SolveStatus::kDegenerateGeometry;
    return result;
  }

  result.p_world_anchor = p_world_tag[j] + x.head<3>();
  result.bias_m = x(3);
  result.covariance =
      PropagatedCovariance(rows, p_world_tag, range_m, normal_inverse, x, prior_weight, height_prior);
  if (height_prior) result.height_information = 1.0 / (height_prior->sigma_m * height_prior->sigma_m);
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
