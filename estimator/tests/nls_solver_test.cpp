#include "anchorbench/estimator/nls_solver.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::estimator {
namespace {

// 400 tags in a box of half-size 5 m around `center`, the anchor at (0, 0, 3), 0.1 m noise and
// bias, and a share of NLOS-like outliers: ranges too long by U(0, max_excess_m), at least 1 m.
testing::AnchorData OutlierBox(std::uint64_t seed, const Eigen::Vector3d& center, double share, double max_excess_m) {
  auto rng = testing::TestStream(seed);
  auto data = testing::BoxData(rng, 400, Eigen::Vector3d(0, 0, 3), center, 5.0, 0.1, 0.1);
  for (double& d : data.range_m)
    if (rng.Uniform() < share) d += rng.Uniform(1.0, max_excess_m);
  return data;
}

// 300 tags in a box of half-size 5 m around (4, 0, 1), the anchor at (1, 2, 3), 0.1 m bias and
// 0.05 m noise: a geometry every kernel converges on.
testing::AnchorData GoodBox(std::uint64_t seed) {
  auto rng = testing::TestStream(seed);
  return testing::BoxData(rng, 300, Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 0, 1), 5.0, 0.1, 0.05);
}

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

// Medians over 20 trials: in about one box trial in five (35 and 45 of 200 with two generators)
// the one-sided outliers pull the L2 warm start far enough that the kernel collapses to alpha_min
// and the estimate drifts metres away, so a mean over 20 trials is a matter of luck.
TEST(NlsSolver, AdaptiveKernelResistsOutliersBetterThanL2) {
  std::vector<double> error_l2, error_adaptive;
  for (int trial = 0; trial < 20; ++trial) {
    const auto data = OutlierBox(300 + trial, Eigen::Vector3d(6, 0, 1), 0.2, 8.0);
    const Eigen::Vector3d& p_anchor = data.p_world_anchor;
    const AnchorSolver l2({{}, Options(KernelMode::kL2), std::nullopt, {}});
    const AnchorSolver adaptive({{}, Options(KernelMode::kAdaptive), std::nullopt, {}});
    const SolveResult a = adaptive.Solve(data.p_world_tag, data.range_m);
    const SolveResult b = l2.Solve(data.p_world_tag, data.range_m);
    ASSERT_TRUE(Succeeded(a.status));
    EXPECT_LT(a.alpha, 1.0);  // the kernel noticed the heavy tail
    error_adaptive.push_back((a.p_world_anchor - p_anchor).norm());
    error_l2.push_back((b.p_world_anchor - p_anchor).norm());
  }
  EXPECT_LT(testing::Median(error_adaptive), 0.1);
  EXPECT_LT(testing::Median(error_adaptive), 0.2 * testing::Median(error_l2));
}

// A solve started metres from the anchor (6 m and more): it takes several iterations.
SolveResult FromAfar(const NlsOptions& options, const testing::AnchorData& data) {
  return NlsSolver(options).Solve(data.p_world_tag, data.range_m, Eigen::Vector3d(6, -3, 0), 0.0);
}

// An iteration budget too small to converge ends in kMaxIterations, which counts as a success
// (the best estimate reached), with exactly the budget spent, per stage.
TEST(NlsSolver, AnIterationBudgetSpentEndsInMaxIterations) {
  const auto data = GoodBox(410);
  for (KernelMode kernel : {KernelMode::kL2, KernelMode::kAdaptive}) {
    NlsOptions options = Options(kernel);
    options.max_iterations = 2;
    const SolveResult result = FromAfar(options, data);
    EXPECT_EQ(result.status, SolveStatus::kMaxIterations) << ToString(kernel);
    EXPECT_TRUE(Succeeded(result.status));
    EXPECT_EQ(result.iterations, kernel == KernelMode::kL2 ? 2 : 4);  // the adaptive mode's L2 warm start too
    options.max_iterations = 50;
    EXPECT_EQ(FromAfar(options, data).status,
              SolveStatus::kConverged);
  }
}

// A pass budget too small ends in kBudgetSpent, a failure; one large enough changes nothing, to
// the bit (AnchorInitializer.ASpentSolveBudgetIsAFailedSolve: what an initializer does with it).
TEST(NlsSolver, APassBudgetSpentIsAFailureAndAnAmpleOneChangesNothing) {
  const auto data = GoodBox(440);
  for (KernelMode kernel : {KernelMode::kL2, KernelMode::kAdaptive}) {
    NlsOptions options = Options(kernel);
    const SolveResult free = FromAfar(options, data);
    options.max_passes = 3;
    const SolveResult cut = FromAfar(options, data);
    EXPECT_EQ(cut.status, SolveStatus::kBudgetSpent) << ToString(kernel);
    EXPECT_FALSE(Succeeded(cut.status));
    options.max_passes = 10000;
    const SolveResult ample = FromAfar(options, data);
    EXPECT_EQ(ample.status, free.status);
    EXPECT_EQ(ample.p_world_anchor, free.p_world_anchor);
    EXPECT_EQ(ample.covariance, free.covariance);
  }
  NlsOptions tight = Options(KernelMode::kAdaptive);
  tight.max_passes = 1;
  std::string why;
  EXPECT_TRUE(tight.IsValid(&why));
  tight.max_passes = -1;
  EXPECT_FALSE(tight.IsValid(&why));
  EXPECT_EQ(why.rfind("max_passes", 0), 0u) << why;
}

// A fixed shape keeps alpha where it is set, and Cauchy (alpha 0) resists the outliers where L2
// does not.
TEST(NlsSolver, AFixedKernelKeepsItsShape) {
  std::vector<double> error_cauchy, error_l2;
  for (int trial = 0; trial < 9; ++trial) {
    const auto data = OutlierBox(420 + trial, Eigen::Vector3d(2, 0, 1), 0.1, 4.0);
    const Eigen::Vector3d& p_anchor = data.p_world_anchor;
    NlsOptions options = Options(KernelMode::kFixed);
    options.fixed_alpha = 0.0;
    const SolveResult cauchy = NlsSolver(options).Solve(data.p_world_tag, data.range_m, p_anchor, 0.0);
    ASSERT_TRUE(Succeeded(cauchy.status));
    EXPECT_EQ(cauchy.alpha, 0.0);
    const SolveResult l2 = NlsSolver(Options(KernelMode::kL2)).Solve(data.p_world_tag, data.range_m, p_anchor, 0.0);
    EXPECT_EQ(l2.alpha, 2.0);
    error_cauchy.push_back((cauchy.p_world_anchor - p_anchor).norm());
    error_l2.push_back((l2.p_world_anchor - p_anchor).norm());
  }
  EXPECT_LT(testing::Median(error_cauchy), 0.5 * testing::Median(error_l2));
}

// Without the L2 warm start the adaptive stage starts at the seed itself: from the truth the
// result is the same minimum as with it; from a seed metres away it spends no L2 iterations.
TEST(NlsSolver, WithoutTheL2WarmStartTheAdaptiveStageStartsAtTheSeed) {
  const auto data = GoodBox(430);
  const Eigen::Vector3d& p_anchor = data.p_world_anchor;
  NlsOptions warm = Options(KernelMode::kAdaptive);
  NlsOptions cold = warm;
  cold.l2_warm_start = false;
  const SolveResult a = NlsSolver(warm).Solve(data.p_world_tag, data.range_m, p_anchor, 0.1);
  const SolveResult b = NlsSolver(cold).Solve(data.p_world_tag, data.range_m, p_anchor, 0.1);
  ASSERT_TRUE(Succeeded(a.status) && Succeeded(b.status));
  EXPECT_LT((a.p_world_anchor - b.p_world_anchor).norm(), 1e-3);
  EXPECT_LT((b.p_world_anchor - p_anchor).norm(), 0.05);
  NlsOptions cold_once = cold, warm_once = warm;
  cold_once.max_iterations = warm_once.max_iterations = 1;
  // One iteration per stage: the cold solve runs one, the warm one two (L2, then adaptive).
  EXPECT_EQ(NlsSolver(cold_once).Solve(data.p_world_tag, data.range_m, p_anchor, 0.1).iterations, 1);
  EXPECT_EQ(NlsSolver(warm_once).Solve(data.p_world_tag, data.range_m, p_anchor, 0.1).iterations, 2);
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
