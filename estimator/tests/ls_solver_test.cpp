#include "anchorbench/estimator/ls_solver.hpp"

#include <gtest/gtest.h>

#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::estimator {
namespace {

TEST(DoubleDifferenceLs, RecoversAnchorAndBiasExactlyOnNoiseFreeData) {
  for (LsPivot pivot : {LsPivot::kShortestRange, LsPivot::kMinimumVariance}) {
    for (int trial = 0; trial < 20; ++trial) {
      auto rng = testing::TestStream(100 + trial);
      const Eigen::Vector3d p_anchor = testing::UniformIn(rng, Eigen::Vector3d(-50, -50, 0), Eigen::Vector3d(50, 50, 5));
      const double bias = rng.Uniform(-0.5, 0.5);
      const auto data = testing::BoxData(rng, 40, p_anchor, p_anchor + Eigen::Vector3d(6, -3, 0), 4.0, bias, 0.0);
      LsOptions options;
      options.pivot = pivot;
      const SolveResult result = SolveDoubleDifferenceLs(data.p_world_tag, data.range_m, options);
      ASSERT_EQ(result.status, SolveStatus::kConverged);
      EXPECT_LT((result.p_world_anchor - p_anchor).norm(), 1e-8);
      EXPECT_NEAR(result.bias_m, bias, 1e-8);
    }
  }
}

// Total least squares: exact on noise-free data like the ordinary one; on noisy data a different
// solution of comparable accuracy (it weighs errors in A as well as in b).
TEST(DoubleDifferenceLs, TotalLeastSquaresIsExactWithoutNoiseAndDiffersWithIt) {
  LsOptions total;
  total.method = LsMethod::kTotal;
  for (int trial = 0; trial < 10; ++trial) {
    auto rng = testing::TestStream(200 + trial);
    const Eigen::Vector3d p_anchor = testing::UniformIn(rng, Eigen::Vector3d(-20, -20, 0), Eigen::Vector3d(20, 20, 5));
    const auto exact = testing::BoxData(rng, 60, p_anchor, p_anchor + Eigen::Vector3d(6, -3, 0), 4.0, 0.2, 0.0);
    const SolveResult tls = SolveDoubleDifferenceLs(exact.p_world_tag, exact.range_m, total);
    ASSERT_EQ(tls.status, SolveStatus::kConverged);
    EXPECT_LT((tls.p_world_anchor - p_anchor).norm(), 1e-6);
    EXPECT_NEAR(tls.bias_m, 0.2, 1e-6);
    const auto noisy = testing::BoxData(rng, 400, p_anchor, p_anchor + Eigen::Vector3d(6, -3, 0), 4.0, 0.2, 0.1);
    const SolveResult ols = SolveDoubleDifferenceLs(noisy.p_world_tag, noisy.range_m);
    const SolveResult tls_noisy = SolveDoubleDifferenceLs(noisy.p_world_tag, noisy.range_m, total);
    ASSERT_EQ(tls_noisy.status, SolveStatus::kConverged);
    EXPECT_GT((tls_noisy.p_world_anchor - ols.p_world_anchor).norm(), 1e-9);
    EXPECT_LT((tls_noisy.p_world_anchor - p_anchor).norm(), 1.0);
  }
  LsMethod method;
  EXPECT_TRUE(ParseLsMethod("total", &method));
  EXPECT_EQ(method, LsMethod::kTotal);
  EXPECT_FALSE(ParseLsMethod("tls", &method));
}

TEST(DoubleDifferenceLs, CollinearPositionsAreDegenerateNotNan) {
  std::vector<Eigen::Vector3d> p;
  std::vector<double> d;
  const Eigen::Vector3d p_anchor(3, 4, 2);
  for (int k = 0; k < 50; ++k) {
    p.emplace_back(0.2 * k, 0.0, 1.0);
    d.push_back((p.back() - p_anchor).norm() + 0.1);
  }
  const SolveResult result = SolveDoubleDifferenceLs(p, d);
  EXPECT_EQ(result.status, SolveStatus::kDegenerateGeometry);
  EXPECT_TRUE(result.p_world_anchor.allFinite());
}

// The bias-free reading: exact where the ranges are plain distances, off where they carry a bias
// (which the full fit recovers), and none for a line of tags or too few samples.
TEST(BiasFreeLs, IsExactOnDistancesAndNoneWhereSingular) {
  for (int trial = 0; trial < 10; ++trial) {
    auto rng = testing::TestStream(300 + trial);
    const Eigen::Vector3d p_anchor = testing::UniformIn(rng, Eigen::Vector3d(-20, -20, 0), Eigen::Vector3d(20, 20, 5));
    const auto distances = testing::BoxData(rng, 40, p_anchor, p_anchor + Eigen::Vector3d(6, -3, 0), 4.0, 0.0, 0.0);
    const std::optional<Eigen::Vector3d> exact = SolveBiasFreeLs(distances.p_world_tag, distances.range_m);
    ASSERT_TRUE(exact);
    EXPECT_LT((*exact - p_anchor).norm(), 1e-8);
    const auto biased = testing::BoxData(rng, 40, p_anchor, p_anchor + Eigen::Vector3d(6, -3, 0), 4.0, 0.5, 0.0);
    const std::optional<Eigen::Vector3d> off = SolveBiasFreeLs(biased.p_world_tag, biased.range_m);
    ASSERT_TRUE(off);
    EXPECT_GT((*off - p_anchor).norm(), 0.05);
  }
  std::vector<Eigen::Vector3d> line;
  std::vector<double> d;
  for (int k = 0; k < 50; ++k) {
    line.emplace_back(0.2 * k, 0.0, 1.0);
    d.push_back((line.back() - Eigen::Vector3d(3, 4, 2)).norm());
  }
  EXPECT_FALSE(SolveBiasFreeLs(line, d));
  EXPECT_FALSE(SolveBiasFreeLs(std::span(line).first(3), std::span(d).first(3)));
}

TEST(DoubleDifferenceLs, TooFewSamples) {
  const std::vector<Eigen::Vector3d> p(3, Eigen::Vector3d::Zero());
  const std::vector<double> d(3, 1.0);
  EXPECT_EQ(SolveDoubleDifferenceLs(p, d).status, SolveStatus::kTooFewSamples);
}

}  // namespace
}  // namespace anchorbench::estimator
