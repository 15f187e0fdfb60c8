#include "anchorbench/estimator/nls_solver.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::estimator {
namespace {

NlsOptions Options(KernelMode kernel) {
  NlsOptions options;
  options.kernel = kernel;
  options.kernel_scale_m = 0.1;
  return options;
}

TEST(NlsSolver, ConvergesFromPerturbedStartOnNoiseFreeData) {
  for (KernelMode kernel : {KernelMode::kL2, KernelMode::kAdaptive}) {
    const NlsSolver solver(Options(kernel));
    for (int trial = 0; trial < 20; ++trial) {
      auto rng = testing::TestStream(200 + trial);
      const Eigen::Vector3d p_anchor = testing::UniformIn(rng, Eigen::Vector3d(-20, -20, 0), Eigen::Vector3d(20, 20, 5));
      const auto data = testing::BoxData(rng, 200, p_anchor, p_anchor + Eigen::Vector3d(5, 2, -1), 5.0, 0.2, 0.0);
      const Eigen::Vector3d start = p_anchor + testing::UniformIn(rng, Eigen::Vector3d::Constant(-1.5), Eigen::Vector3d::Constant(1.5));
      const SolveResult result = solver.Solve(data.p_world_tag, data.range_m, start, 0.0);
      ASSERT_TRUE(Succeeded(result.status)) << ToString(result.status);
      EXPECT_LT((result.p_world_anchor - p_anchor).norm(), 1e-6) << "trial " << trial;
      EXPECT_NEAR(result.bias_m, 0.2, 1e-6);
      EXPECT_GT(result.iterations, 0);
      EXPECT_TRUE(result.covariance.allFinite());
    }
  }
}

TEST(NlsSolver, AdaptiveKernelResistsOutliersBetterThanL2) {
  double error_l2 = 0.0, error_adaptive = 0.0;
  for (int trial = 0; trial < 20; ++trial) {
    auto rng = testing::TestStream(300 + trial);
    const Eigen::Vector3d p_anchor(0, 0, 3);
    auto data = testing::BoxData(rng, 400, p_anchor, Eigen::Vector3d(6, 0, 1), 5.0, 0.1, 0.1);
    for (double& d : data.range_m)
      if (rng.Uniform() < 0.2) d += rng.Uniform(1.0, 8.0);  // NLOS-like outliers
    const AnchorSolver l2({{}, Options(KernelMode::kL2), std::nullopt, {}});
    const AnchorSolver adaptive({{}, Options(KernelMode::kAdaptive), std::nullopt, {}});
    const SolveResult a = adaptive.Solve(data.p_world_tag, data.range_m);
    const SolveResult b = l2.Solve(data.p_world_tag, data.range_m);
    ASSERT_TRUE(Succeeded(a.status));
    EXPECT_LT(a.alpha, 1.0);  // the kernel noticed the heavy tail
    error_adaptive += (a.p_world_anchor - p_anchor).norm() / 20;
    error_l2 += (b.p_world_anchor - p_anchor).norm() / 20;
  }
  EXPECT_LT(error_adaptive, 0.3);
  EXPECT_LT(error_adaptive, 0.5 * error_l2);
}

TEST(NlsSolver, CollinearPositionsGiveFailureStatusWithoutNan) {
  std::vector<Eigen::Vector3d> p;
  std::vector<double> d;
  const Eigen::Vector3d p_anchor(3, 4, 2);
  for (int k = 0; k < 100; ++k) {
    p.emplace_back(0.2 * k, 0.0, 1.0);
    d.push_back((p.back() - p_anchor).norm());
  }
  for (KernelMode kernel : {KernelMode::kL2, KernelMode::kAdaptive}) {
    const SolveResult result = NlsSolver(Options(kernel)).Solve(p, d, Eigen::Vector3d(2, 2, 2), 0.0);
    EXPECT_EQ(result.status, SolveStatus::kDegenerateGeometry);
    EXPECT_TRUE(result.p_world_anchor.allFinite());
  }
}

}  // namespace
}  // namespace anchorbench::estimator
