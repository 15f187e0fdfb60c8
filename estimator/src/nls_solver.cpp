#include "anchorbench/estimator/nls_solver.hpp"

#include <cmath>
#include <limits>
#include <utility>
#include <optional>

#include "anchorbench/estimator/solver.hpp"
#include "numerics.hpp"
#include "residual_arrays.hpp"

namespace anchorbench::estimator {
namespace {

// Levenberg-Marquardt's damping schedule (the common one, e.g. Nocedal & Wright): the damping,
// relative to diag(J^T W J), shrinks 10x after an accepted step and grows 10x after a rejected one,
// up to kMaxDampingIncreases times per iteration (12: from 1e-8 to 1e4, where the step is a
// gradient step a hundred-thousandth of the Gauss-Newton one). The floors keep it meaningful in
// double precision and keep a direction without information from dividing by zero.
constexpr int kMaxDampingIncreases = 12;
constexpr double kDampingDecrease = 0.1;
constexpr double kDampingIncrease = 10.0;
constexpr double kMinDampingAfterSuccess = 1e-12;
constexpr double kMinDampingAfterFailure = 1e-8;
constexpr double kMinDiagonal = 1e-12;

using Vector4 = Eigen::Vector4d;

// The height prior as a quadratic term (no kernel: the prior is not an outlier candidate) in the
// units of the passes, whose sums leave out the common factor 1/c^2: cost 0.5 ((z - z0)/sigma)^2,
// information c^2/sigma^2 on z and gradient c^2 (z - z0)/sigma^2. Absent: zero, exactly.
class PriorTerm {
 public:
  PriorTerm(const std::optional<HeightPrior>& prior, double kernel_scale_m) : prior_(prior) {
    if (prior_) weight_ = kernel_scale_m * kernel_scale_m / (prior_->sigma_m * prior_->sigma_m);
  }
  double weight() const { return weight_; }  // beside one unit-weight range
  double Cost(const Vector4& theta) const { return prior_ ? 0.5 * prior_->Chi2(theta(2)) : 0.0; }
  void AddTo(const Vector4& theta, Eigen::Matrix4d* information, Vector4* gradient) const {
    if (!prior_) return;
    (*information)(2, 2) += weight_;
    (*gradient)(2) += weight_ * (theta(2) - prior_->z_world_m);
  }

 private:
  std::optional<HeightPrior> prior_;
  double weight_ = 0.0;
};

// The summary of a refined estimate from its normal equations (see SummarizeSolution).
SolveResult Summary(const Vector4& theta, double alpha, const internal::PassResult& eq, std::size_t n,
                    SolveStatus status, int iterations, const std::optional<HeightPrior>& prior = std::nullopt) {
  SolveResult result;
  if (!theta.allFinite() || !eq.information.allFinite() || !std::isfinite(eq.cost)) {
    result.status = SolveStatus::kNumericalFailure;
    return result;
  }
  result.p_world_anchor = theta.head<3>();
  result.bias_m = theta(3);
  result.alpha = alpha;
  result.iterations = iterations;
  result.final_cost = eq.cost + (prior ? 0.5 * prior->Chi2(theta(2)) : 0.0);
  result.status = status;
  // For alpha = 2 this is the usual sigma^2 (J^T J)^-1; a prior adds its information 1/sigma^2
  // to the data's (J^T W J) / s^2.
  const double s2 = eq.weighted_squares / static_cast<double>(n - 4);
  Eigen::Matrix4d information = eq.information;
  if (prior) information = information / s2 + Eigen::Vector4d::UnitZ() * Eigen::Vector4d::UnitZ().transpose() /
                                                  (prior->sigma_m * prior->sigma_m);
  Eigen::Matrix4d information_inverse;
  if (!internal::InvertNormalMatrix(information, &information_inverse)) {
    result.status = SolveStatus::kDegenerateGeometry;
    return result;
  }
  result.covariance = prior ? information_inverse : Eigen::Matrix4d(s2 * information_inverse);
  if (prior) result.height_information = 1.0 / (prior->sigma_m * prior->sigma_m);
  return result;
}

// The covariance of an M-estimate (Huber 1981, ch. 7): the score sum psi(x_k) j_k = 0, with
// psi(x) = x w(x) on the normalized residuals x = r / c, gives
//   Cov = c^2 N/(N-4) B^-1 (sum psi(x_k)^2 j_k j_k^T) B^-1,  B = sum psi'(x_k) j_k j_k^T.
// s^2 (J^T W J)^-1 takes the down-weighted residuals for the noise and under-states it (lm_huber
// 1.5x and lm_cauchy 1.8x over-confident on white noise, where L2 is credible). For alpha < 2
// only; none when B is not positive definite (a redescending kernel with most residuals far out).
std::optional<Eigen::Matrix4d> RobustCovariance(std::span<const Eigen::Vector3d> p_world_tag,
                                                std::span<const double> range_m, const Vector4& theta, double alpha,
                                                double c) {
  constexpr double kStep = 1e-4;  // of x, for psi' by central differences
  const auto psi = [alpha](double x) { return x * Weight(x, alpha); };
  Eigen::Matrix4d bread = Eigen::Matrix4d::Zero(), meat = Eigen::Matrix4d::Zero();
  for (std::size_t k = 0; k < range_m.size(); ++k) {
    const Eigen::Vector3d diff = p_world_tag[k] - theta.head<3>();
    const double distance_m = diff.norm();
    if (!(distance_m > 0.0)) continue;
    Vector4 j;
    j << -diff / distance_m, 1.0;
    const double x = (distance_m + theta(3) - range_m[k]) / c;
    const double slope = (psi(x + kStep) - psi(x - kStep)) / (2.0 * kStep);
    bread.noalias() += slope * j * j.transpose();
    meat.noalias() += psi(x) * psi(x) * j * j.transpose();
  }
  Eigen::Matrix4d bread_inverse;
  if (!internal::InvertNormalMatrix(bread, &bread_inverse)) return std::nullopt;
  const double n = static_cast<double>(range_m.size());
  return Eigen::Matrix4d(c * c * n / (n - 4.0) * bread_inverse * meat * bread_inverse);
}

}  // namespace

bool NlsOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* message) {
    if (why) *why = message;
    return false;
  };
  // Below about -1000 the kernel is flat to double precision: nothing would distinguish alphas.
  if (!(alpha_min >= -1000.0 && alpha_min < 2.0)) return fail("alpha_min must be in [-1000, 2)");
  if (!(fixed_alpha >= -1000.0 && fixed_alpha <= 2.0)) return fail("fixed_alpha must be in [-1000, 2]");
  if (!(kernel_scale_m > 0.0 && kernel_scale_m <= 1e4)) return fail("kernel_scale_m must be in (0, 1e4]");
  if (!(truncation > 0.0 && truncation <= 1e4)) return fail("truncation must be in (0, 1e4]");
  if (max_iterations < 1 || max_iterations > 100000) return fail("max_iterations must be in [1, 100000]");
  if (!(step_tolerance_m > 0.0 && step_tolerance_m <= 1e3)) return fail("step_tolerance_m must be in (0, 1e3]");
  if (!(alpha_tolerance > 0.0 && alpha_tolerance <= 10.0)) return fail("alpha_tolerance must be in (0, 10]");
  if (!(initial_damping >= 0.0 && initial_damping <= 1e12)) return fail("initial_damping must be in [0, 1e12]");
  if (max_passes < 0 || max_passes > 100000000) return fail("max_passes must be in [0, 1e8] (0: no budget)");
  return true;
}

NlsSolver::NlsSolver(const NlsOptions& options, std::shared_ptr<const LogPartitionTable> table)
    : options_(options), table_(std::move(table)) {
  if (options_.kernel != KernelMode::kAdaptive) {
    table_.reset();
  } else if (!table_ || table_->truncation() != options_.truncation || table_->alpha_min() != options_.alpha_min) {
    table_ = MakeLogPartitionTable(options_.truncation, options_.alpha_min);
  }
}

NlsSolver::Stage NlsSolver::Refine(const internal::SampleArrays& samples, const Eigen::Vector4d& theta_initial,
                                   std::optional<double> fixed_alpha, double step_tolerance_m,
                                   const std::optional<HeightPrior>& height_prior, long* passes_left) const {
  // Every pass over the samples spends the budget; none left: the solve stops where it is.
  const auto Pass = [passes_left](const internal::SampleArrays& all, const Vector4& at, double scale_m,
                                   const internal::PassRequest& request) {
    if (*passes_left > 0) --*passes_left;
    return internal::Pass(all, at, scale_m, request);
  };
  const auto spent = [passes_left] { return *passes_left == 0; };
  const bool adaptive = !fixed_alpha.has_value();
  const double c = options_.kernel_scale_m;
  const PriorTerm prior(height_prior, c);
  // The alternation keeps the histogram of the accepted residuals; candidates fill their own.
  std::optional<AlphaSelector> selector, candidate_histogram;
  if (adaptive) {
    selector.emplace(table_);
    candidate_histogram.emplace(table_);
  }

  Stage stage{theta_initial, fixed_alpha.value_or(2.0), 0, SolveStatus::kMaxIterations};
  double damping = options_.initial_damping;
  // One pass per LM iteration in the steady state: a candidate step's pass sums its cost, its
  // normal equations and (adaptive) its residual histogram, so an accepted step's pass serves the
  // next iteration. The adaptive alternation re-sums the equations only when the alpha step moves
  // alpha by alpha_tolerance or more (ours: a smaller move is below what convergence resolves, and
  // keeping the shape spares a second pass per iteration).
  internal::PassResult eq = Pass(samples, stage.theta, c, {stage.alpha, true, true, adaptive ? &*selector : nullptr});
  while (stage.iterations < options_.max_iterations) {
    const double previous_alpha = stage.alpha;
    if (spent()) {
      stage.status = SolveStatus::kBudgetSpent;
      return stage;
    }
    if (adaptive) {  // Eq. (12): the alpha step of the alternation
      const double alpha = selector->Select(stage.iterations == 0 ? std::nullopt : std::optional<double>(stage.alpha));
      if (stage.iterations == 0 || std::abs(alpha - stage.alpha) >= options_.alpha_tolerance) {
        stage.alpha = alpha;
        eq = Pass(samples, stage.theta, c, {stage.alpha, true, true, nullptr});
      }
    }
    if (!std::isfinite(eq.cost) || !eq.information.allFinite()) {
      stage.status = SolveStatus::kNumericalFailure;
      return stage;
    }
    // Damped step (J^T W J + lambda diag) delta = -J^T W r, raised until the cost drops.
    Eigen::Matrix4d information = eq.information;
    Vector4 gradient = eq.gradient;
    prior.AddTo(stage.theta, &information, &gradient);
    const double cost = eq.cost + prior.Cost(stage.theta);
    bool accepted = false;
    Vector4 delta = Vector4::Zero();
    for (int attempt = 0; attempt < kMaxDampingIncreases && !accepted && !spent(); ++attempt) {
      Eigen::Matrix4d damped = information;
      damped.diagonal() += damping * information.diagonal().cwiseMax(kMinDiagonal);
      delta = damped.ldlt().solve(-gradient);
      if (!delta.allFinite()) break;
      internal::PassResult candidate = Pass(samples, stage.theta + delta, c,
                                            {stage.alpha, true, true, adaptive ? &*candidate_histogram : nullptr});
      if (candidate.cost + prior.Cost(stage.theta + delta) <= cost) {
        accepted = true;
        stage.theta += delta;
        eq = candidate;
        if (adaptive) std::swap(*selector, *candidate_histogram);
        damping = std::max(damping * kDampingDecrease, kMinDampingAfterSuccess);
      } else {
        damping = std::max(damping * kDampingIncrease, kMinDampingAfterFailure);
      }
    }
    ++stage.iterations;
    if (!accepted && spent()) {
      stage.status = SolveStatus::kBudgetSpent;
      return stage;
    }
    if (!accepted) {
      // No step lowers the cost: theta is a minimum for this alpha.
      stage.status = SolveStatus::kConverged;
      break;
    }
    if (delta.norm() < step_tolerance_m && std::abs(stage.alpha - previous_alpha) < options_.alpha_tolerance) {
      stage.status = SolveStatus::kConverged;
      break;
    }
  }
  stage.information = eq.information;  // the summary's: at the final theta and alpha
  stage.cost = eq.cost;
  stage.weighted_squares = eq.weighted_squares;
  return stage;
}

SolveResult NlsSolver::Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                             const Eigen::Vector3d& p_world_anchor_initial, double bias_initial_m,
                             const std::optional<HeightPrior>& height_prior) const {
  SolveResult result;
  const std::size_t n = range_m.size();
  if (n < kMinSamplesNls || p_world_tag.size() != n) {
    result.status = SolveStatus::kTooFewSamples;
    return result;
  }
  Vector4 theta;
  theta << p_world_anchor_initial, bias_initial_m;
  Stage stage{theta, 2.0, 0, SolveStatus::kConverged};
  const internal::SampleArrays samples(p_world_tag, range_m);
  long passes_left = options_.max_passes > 0 ? options_.max_passes : -1;
  if (options_.kernel == KernelMode::kL2) {
    stage = Refine(samples, theta, 2.0, options_.step_tolerance_m, height_prior, &passes_left);
  } else {
    if (options_.l2_warm_start) {  // only into the basin: 10x the step tolerance
      stage = Refine(samples, theta, 2.0, 10.0 * options_.step_tolerance_m, height_prior, &passes_left);
    }
    if (stage.status != SolveStatus::kNumericalFailure && stage.status != SolveStatus::kBudgetSpent) {
      const int used = stage.iterations;
      const std::optional<double> alpha =
          options_.kernel == KernelMode::kFixed ? std::optional<double>(options_.fixed_alpha) : std::nullopt;
      stage = Refine(samples, stage.theta, alpha, options_.step_tolerance_m, height_prior, &passes_left);
      stage.iterations += used;
    }
  }
  if (stage.status == SolveStatus::kNumericalFailure || stage.status == SolveStatus::kBudgetSpent) {
    result.status = stage.status;
    return result;
  }
  internal::PassResult equations;
  equations.information = stage.information;
  equations.cost = stage.cost;
  equations.weighted_squares = stage.weighted_squares;
  SolveResult summary = Summary(stage.theta, stage.alpha, equations, n, stage.status, stage.iterations, height_prior);
  if (height_prior) summary.height_weight = PriorTerm(height_prior, options_.kernel_scale_m).weight();
  constexpr double kL2 = 2.0 - 1e-9;  // at alpha = 2 the M-estimate is least squares: s^2 (J^T J)^-1 stands
  if (Succeeded(summary.status) && stage.alpha < kL2 && !height_prior) {
    if (const std::optional<Eigen::Matrix4d> robust =
            RobustCovariance(p_world_tag, range_m, stage.theta, stage.alpha, options_.kernel_scale_m)) {
      summary.covariance = *robust;
    }
  }
  return summary;
}

SolveResult SummarizeSolution(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                              const Eigen::Vector4d& theta, double alpha, double kernel_scale_m, SolveStatus status,
                              int iterations) {
  const internal::PassResult equations =
      internal::Pass(internal::SampleArrays(p_world_tag, range_m), theta, kernel_scale_m, {alpha, true, true, nullptr});
  return Summary(theta, alpha, equations, range_m.size(), status, iterations);
}

}  // namespace anchorbench::estimator
