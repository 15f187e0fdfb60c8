#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "anchorbench/estimator/enum_names.hpp"
#include "anchorbench/estimator/height_prior.hpp"
#include "anchorbench/estimator/solve_result.hpp"
#include "anchorbench/estimator/solver.hpp"

namespace anchorbench::estimator {

enum class LsPivot {
  kShortestRange,    // j = sample with the shortest range
  kMinimumVariance,  // UVIO (Delama et al. 2023): j minimizes d_j^2 sigma_d^2 + sigma_p^2 ||p_j||^2,
                     // rows weighted by the inverse of that variance model (world-frame dependent,
                     // as in the original)
};

inline constexpr EnumNames<LsPivot, 2> kLsPivotNames({
    {LsPivot::kShortestRange, "shortest_range"}, {LsPivot::kMinimumVariance, "minimum_variance"}});
inline std::string_view ToString(LsPivot value) { return kLsPivotNames.Name(value); }
inline bool ParseLsPivot(std::string_view name, LsPivot* value) { return kLsPivotNames.Parse(name, value); }

enum class LsMethod {
  kOrdinary,  // min ||A x - b||: errors in b only (our default; every committed result uses it)
  kTotal,     // total least squares, errors in A and b alike: the paper's name for its linear step
};
inline constexpr EnumNames<LsMethod, 2> kLsMethodNames({
    {LsMethod::kOrdinary, "ordinary"}, {LsMethod::kTotal, "total"}});
inline std::string_view ToString(LsMethod value) { return kLsMethodNames.Name(value); }
inline bool ParseLsMethod(std::string_view name, LsMethod* value) { return kLsMethodNames.Parse(name, value); }

struct LsOptions {
  LsMethod method = LsMethod::kOrdinary;
  LsPivot pivot = LsPivot::kShortestRange;
  double sigma_range_m = 0.1;     // for kMinimumVariance only
  double sigma_position_m = 0.05;  // for kMinimumVariance only

  bool IsValid(std::string* why) const;
};

// Coarse solution of Sec. III-D: double-difference least squares A x = b, x = [p_A; gamma],
//   A_k = [-(p_k - p_j)^T, d_k - d_j]                                   Eq. (9)
//   b_k = ((d_k^2 - d_j^2) - (||p_k||^2 - ||p_j||^2)) / 2               Eq. (10)
// Solved through the 4x4 normal equations accumulated in one O(N) pass (no N x 4 matrix), with
// positions taken relative to p_j so the squared norms do not cancel far from the origin.
// Ordinary least squares on these rows by default; the paper calls its linear step total least
// squares, which LsMethod::kTotal solves: the eigenvector of the smallest eigenvalue of
// [A b]^T W [A b] (5x5, from the same one pass), in the rows' own units (m and m^2, unscaled). The
// covariance is s^2 (A^T W A)^-1 at the solution for both (for TLS a first-order stand-in).
// A height prior adds the row [0 0 1 0] x = z_prior, weighted by the rows' residual variance with
// the height held at the prior over sigma^2 (ours: the rows are in m^2, the prior in m).
SolveResult SolveDoubleDifferenceLs(std::span<const Eigen::Vector3d> p_world_tag,
                                    std::span<const double> range_m, const LsOptions& options = {},
                                    const std::optional<HeightPrior>& height_prior = std::nullopt);

// The anchor position that reads the ranges as plain distances (the bias held at 0): Eq. (9)-(10)
// without the bias column, the position block of the same normal equations. None where singular.
// Where a far anchor is seen from a short path, range and bias trade off along a long valley whose
// minima can lie metres apart at nearly equal fits; the certificate starts one of its alternatives
// here, at the valley's zero-bias end.
std::optional<Eigen::Vector3d> SolveBiasFreeLs(std::span<const Eigen::Vector3d> p_world_tag,
                                               std::span<const double> range_m);

// The same behind the Solver interface (ls_double, and the pdop_ls trigger's estimate).
class DoubleDifferenceLsSolver : public Solver {
 public:
  explicit DoubleDifferenceLsSolver(const LsOptions& options = {},
                                    const std::optional<HeightPrior>& height_prior = std::nullopt)
      : options_(options), height_prior_(height_prior) {}
  SolveResult Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const override {
    return SolveDoubleDifferenceLs(p_world_tag, range_m, options_, height_prior_);
  }
  std::optional<HeightPrior> height_prior() const override { return height_prior_; }

 private:
  LsOptions options_;
  std::optional<HeightPrior> height_prior_;
};

// The single-difference LS of the authors' earlier library ("SINGLE", constant bias):
// d_k^2 - ||p_k||^2 = -2 p_k^T p_A + 2 d_k gamma + (||p_A||^2 - gamma^2), linear in
// x = [p_A; gamma; ||p_A||^2 - gamma^2] (the last one treated as independent). Positions are taken
// relative to their mean for conditioning.
SolveResult SolveSingleDifferenceLs(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m);

}  // namespace anchorbench::estimator
