#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "anchorbench/estimator/enum_names.hpp"
#include "anchorbench/estimator/height_prior.hpp"
#include "anchorbench/estimator/robust_kernel.hpp"
#include "anchorbench/estimator/solve_result.hpp"

namespace anchorbench::estimator {
namespace internal {
struct SampleArrays;
}  // namespace internal

enum class KernelMode {
  kL2,        // alpha fixed at 2: plain least squares, Eq. (11)
  kAdaptive,  // alpha estimated jointly, Eq. (12)
  kFixed,     // alpha fixed at fixed_alpha (1: smooth Huber / pseudo-Huber, 0: Cauchy, -2: Geman-McClure)
};

inline constexpr EnumNames<KernelMode, 3> kKernelModeNames({
    {KernelMode::kAdaptive, "adaptive"}, {KernelMode::kL2, "l2"}, {KernelMode::kFixed, "fixed"}});
inline std::string_view ToString(KernelMode value) { return kKernelModeNames.Name(value); }
inline bool ParseKernelMode(std::string_view name, KernelMode* value) { return kKernelModeNames.Parse(name, value); }

struct NlsOptions {
  KernelMode kernel = KernelMode::kAdaptive;
  double alpha_min = kDefaultAlphaMin;  // lower end of the alpha search; 2 is the upper end
  double fixed_alpha = 1.0;       // KernelMode::kFixed
  double kernel_scale_m = 0.1;    // c of Eq. (13); the residual scale the kernel treats as "normal"
  double truncation = kDefaultTruncation;  // |r/c| bound of the truncated density's normalizer Z~(alpha)
  int max_iterations = 50;        // LM iterations per stage (L2 warm start, adaptive)
  double step_tolerance_m = 1e-3;  // converged when ||delta theta|| falls below this (1 mm: far below
                                   // any UWB accuracy; the L2 warm start stops at 10x this)...
  double alpha_tolerance = 1e-2;   // ...and alpha moved less than this
  double initial_damping = 1e-4;   // LM lambda, relative to diag(J^T W J)
  // Adaptive mode: first converge with alpha = 2 from the LS seed, then adapt. With outliers the
  // LS seed can sit metres away, where every residual looks like an outlier, alpha collapses to
  // alpha_min and the kernel has no gradient left to follow; the L2 stage brings the estimate
  // into the basin first. (Our choice; the paper does not say how the alternation is started.)
  bool l2_warm_start = true;
  // The work budget of one solve for a live stack, in O(N) passes over the samples (every LM
  // iteration takes one, and one more per rejected damping; both stages count): once spent, the
  // solve stops with kBudgetSpent, a failure, and the initializer retries on more data. The time
  // of a pass is linear in N (bench_solver measures it). The summary adds at most two passes.
  // 0: no budget beyond max_iterations x 12 dampings per stage (the experiments' setting).
  int max_passes = 0;

  bool IsValid(std::string* why) const;
};

// The summary of a refined estimate theta = (p_A, gamma) under the kernel shape alpha: the robust
// cost, the Gauss-Newton covariance s^2 (J^T W J)^-1 with s^2 = sum w r^2 / (N - 4), and
// kDegenerateGeometry when J^T W J is singular. `status` is kept otherwise.
SolveResult SummarizeSolution(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                              const Eigen::Vector4d& theta, double alpha, double kernel_scale_m, SolveStatus status,
                              int iterations);

// Nonlinear refinement of Sec. III-D: Levenberg-Marquardt on theta = (p_A, gamma) with residuals
// r_k = ||p_k - p_A|| + gamma - d_k (Eq. (11)). In adaptive mode each iteration first picks alpha
// from the current residuals (AlphaSelector), then takes one damped IRLS step with weights
// rho'(r)/r at that alpha, accepted only if it lowers sum rho (Eq. (12)). Every iteration is O(N)
// with 4x4 normal equations; nothing is allocated inside the loop.
class NlsSolver {
 public:
  // The adaptive kernel needs the log-partition table of (truncation, alpha_min). Without one (or
  // with one for other settings) the solver takes DefaultLogPartitionTable() for the default
  // settings and builds its own (~40 ms) for others: pass a shared one (LogPartitionTables) then.
  explicit NlsSolver(const NlsOptions& options = {}, std::shared_ptr<const LogPartitionTable> table = nullptr);

  // With a height prior, the cost gains 0.5 ((z_A - z_prior) / sigma)^2 (quadratic: the prior is
  // not an outlier candidate) and the covariance its information.
  SolveResult Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                    const Eigen::Vector3d& p_world_anchor_initial, double bias_initial_m,
                    const std::optional<HeightPrior>& height_prior = std::nullopt) const;

  const NlsOptions& options() const { return options_; }
  // The adaptive kernel's log-partition table (none for the other kernels).
  const std::shared_ptr<const LogPartitionTable>& table() const { return table_; }

 private:
  struct Stage {
    Eigen::Vector4d theta;
    double alpha;
    int iterations;
    SolveStatus status;
    // The normal equations at (theta, alpha), from the stage's last pass: the summary needs no
    // pass of its own.
    Eigen::Matrix4d information = Eigen::Matrix4d::Zero();
    double cost = 0.0;
    double weighted_squares = 0.0;
  };
  // LM from theta with the kernel shape fixed at *fixed_alpha, or adaptive when it is empty.
  // `passes_left` is the budget left to the solve (<0: none), spent here.
  Stage Refine(const internal::SampleArrays& samples, const Eigen::Vector4d& theta, std::optional<double> fixed_alpha,
               double step_tolerance_m, const std::optional<HeightPrior>& height_prior, long* passes_left) const;

  NlsOptions options_;
  std::shared_ptr<const LogPartitionTable> table_;  // only for KernelMode::kAdaptive
};

}  // namespace anchorbench::estimator
