// Whether the covariance a solve reports can be trusted: over many noise realizations of the same
// clean geometry, the normalized estimation error squared (NEES) of lm_l2 averages the number of
// parameters, inside the chi-square bounds (Bar-Shalom's consistency test).
#include <cmath>

#include <Eigen/Cholesky>
#include <gtest/gtest.h>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::estimator {
namespace {

// Two-sided 95% bounds of the average of `runs` chi-square variables with `dof` degrees of
// freedom each (Wilson-Hilferty: chi2 of k dof ~ k (1 - 2/(9k) + z sqrt(2/(9k)))^3).
std::pair<double, double> AneesBounds(int runs, int dof) {
  const double k = static_cast<double>(runs) * dof;
  auto quantile = [k](double z) { return k * std::pow(1.0 - 2.0 / (9.0 * k) + z * std::sqrt(2.0 / (9.0 * k)), 3); };
  return {quantile(-1.959964) / runs, quantile(1.959964) / runs};
}

TEST(Covariance, NeesOfL2OnCleanDataIsInsideItsChiSquareBounds) {
  constexpr int kRuns = 400;
  const Eigen::Vector3d p_anchor(2, -1, 3);
  constexpr double kBias = 0.2, kSigma = 0.1;
  AnchorSolverOptions options;
  options.nls.kernel = KernelMode::kL2;
  options.nls.kernel_scale_m = kSigma;
  options.nls.step_tolerance_m = 1e-6;  // converge far below the errors being measured
  const AnchorSolver solver(options);
  double sum_nees = 0.0;
  for (int run = 0; run < kRuns; ++run) {
    auto geometry = testing::TestStream(7);  // the same tag positions in every run...
    auto noise = testing::TestStream(10000 + run);  // ...and new range noise
    auto data = testing::BoxData(geometry, 150, p_anchor, Eigen::Vector3d(6, 2, 1), 5.0, kBias, 0.0);
    for (double& d : data.range_m) d += kSigma * noise.Normal();
    const SolveResult result = solver.Solve(data.p_world_tag, data.range_m);
    ASSERT_TRUE(Succeeded(result.status));
    Eigen::Vector4d error;
    error << result.p_world_anchor - p_anchor, result.bias_m - kBias;
    sum_nees += error.dot(result.covariance.ldlt().solve(error));
  }
  const double anees = sum_nees / kRuns;
  const auto [lower, upper] = AneesBounds(kRuns, 4);  // about 3.80 and 4.20
  EXPECT_GT(anees, lower);
  EXPECT_LT(anees, upper);
}

}  // namespace
}  // namespace anchorbench::estimator
