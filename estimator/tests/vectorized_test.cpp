// The vectorized passes against their scalar definitions: the residual arrays against
// RangeResidual (to the bit), the kernel arrays against EvaluateKernel (to ~1e-15).
#include <cmath>

#include <gtest/gtest.h>

#include "anchorbench/estimator/range_residual.hpp"
#include "anchorbench/estimator/robust_kernel.hpp"
#include "anchorbench/testing/test_data.hpp"
#include "residual_arrays.hpp"

namespace anchorbench::estimator {
namespace {

TEST(Vectorized, ChunkResidualsAreRangeResidualToTheBit) {
  auto rng = testing::TestStream(51);
  const auto data = testing::BoxData(rng, 600, Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 0, 1), 6.0, 0.3, 0.1);
  std::vector<Eigen::Vector3d> p = data.p_world_tag;
  std::vector<double> d = data.range_m;
  const Eigen::Vector4d theta(1.5, 2.25, 2.75, 0.2);
  p.push_back(theta.head<3>());  // a tag exactly at the anchor: no direction, never NaN
  d.push_back(1.0);
  const internal::SampleArrays samples(p, d);  // 601 samples: three chunks, the last one odd
  Eigen::Matrix4d expected = Eigen::Matrix4d::Zero();
  Eigen::Vector4d expected_gradient = Eigen::Vector4d::Zero();
  double expected_cost = 0.0;
  for (Eigen::Index start = 0; start < samples.size(); start += kChunk) {
    const Eigen::Index size = std::min<Eigen::Index>(kChunk, samples.size() - start);
    internal::ChunkResiduals residuals, ranges_only;
    residuals.At(samples, start, size, theta, true);
    ranges_only.At(samples, start, size, theta, false);
    for (Eigen::Index k = 0; k < size; ++k) {
      const auto i = static_cast<std::size_t>(start + k);
      Eigen::Vector4d row;
      const double r = RangeResidual(theta, p[i], d[i], &row);
      EXPECT_EQ(residuals.r[k], r) << i;
      EXPECT_EQ(ranges_only.r[k], r) << i;
      EXPECT_TRUE((Eigen::Vector4d(residuals.ux[k], residuals.uy[k], residuals.uz[k], 1.0) - row).norm() < 1e-15) << i;
      expected += row * row.transpose();
      expected_gradient += r * row;
      expected_cost += 0.5 * (r / 0.1) * (r / 0.1);
    }
  }
  const internal::PassResult pass = internal::Pass(samples, theta, 0.1, {2.0, true, true, nullptr});
  EXPECT_TRUE(pass.information.isApprox(expected, 1e-14));
  EXPECT_TRUE(pass.gradient.isApprox(expected_gradient, 1e-13));
  EXPECT_NEAR(pass.cost, expected_cost, 1e-12 * expected_cost);
}

TEST(Vectorized, KernelArraysAgreeWithTheScalarKernel) {
  Chunk x(2 * 13 * 9 + 1);  // at most kChunk
  Eigen::Index i = 0;
  for (int decade = -8; decade <= 4; ++decade) {
    for (double mantissa : {1.0, 1.7, 2.3, 3.1, 4.4, 5.5, 6.9, 8.6, 9.9}) {
      x[i++] = mantissa * std::pow(10.0, decade);
      x[i++] = -mantissa * std::pow(10.0, decade);
    }
  }
  x[i] = 0.0;
  ASSERT_EQ(i + 1, x.size());
  KernelArrays kernel;
  for (double alpha : {2.0, 1.999, 1.0, 0.5, 1e-5, 0.0, -1e-5, -0.4, -2.0, -7.3, -10.0}) {
    kernel.Evaluate(x, alpha);
    for (Eigen::Index k = 0; k < x.size(); ++k) {
      const KernelValue scalar = EvaluateKernel(x[k], alpha);
      // base^(alpha/2) - 1 cancels in both forms (to ~1e-16 absolute: an ulp of 1), so the bound
      // is relative plus that much absolute.
      EXPECT_NEAR(kernel.rho()[k], scalar.rho, 1e-13 * std::abs(scalar.rho) + 1e-15)
          << "alpha " << alpha << " x " << x[k];
      EXPECT_NEAR(kernel.weight()[k], scalar.weight, 1e-13 * scalar.weight) << "alpha " << alpha << " x " << x[k];
    }
  }
}

TEST(AlphaSelector, BinsAreQuarterOctavesFromTwoToTheMinusSix) {
  EXPECT_EQ(AlphaSelector::BinOf(0.0), 0);
  EXPECT_EQ(AlphaSelector::BinOf(std::ldexp(1.0, -7)), 0);
  EXPECT_EQ(AlphaSelector::BinOf(std::ldexp(1.0, -6)), 1);
  EXPECT_EQ(AlphaSelector::BinOf(1.0), 1 + 4 * 6);
  EXPECT_EQ(AlphaSelector::BinOf(-1.24), 1 + 4 * 6);  // |x|, four bins per octave: 1, 1.25, 1.5, 1.75
  EXPECT_EQ(AlphaSelector::BinOf(1.25), 2 + 4 * 6);
  EXPECT_EQ(AlphaSelector::BinOf(1023.0), AlphaSelector::kBins - 2);
  EXPECT_EQ(AlphaSelector::BinOf(1024.0), AlphaSelector::kBins - 1);
  EXPECT_EQ(AlphaSelector::BinOf(std::numeric_limits<double>::infinity()), AlphaSelector::kBins - 1);
  EXPECT_EQ(AlphaSelector::BinOf(std::numeric_limits<double>::quiet_NaN()), AlphaSelector::kBins - 1);
}

TEST(AlphaSelector, BinsOfOneAndOfManyAgree) {
  auto rng = testing::TestStream(52);
  Chunk x(kChunk);
  for (Eigen::Index k = 0; k < x.size(); ++k) x[k] = rng.Normal() * std::exp(rng.Uniform(-3.0, 8.0));
  auto table = std::make_shared<const LogPartitionTable>(10.0, -10.0);
  AlphaSelector one_by_one(table), all_at_once(table);
  for (Eigen::Index k = 0; k < x.size(); ++k) one_by_one.Add(x[k]);
  all_at_once.AddAll(x);
  for (double alpha : {2.0, 0.0, -5.0}) EXPECT_NEAR(one_by_one.Nll(alpha), all_at_once.Nll(alpha), 1e-9);
}

}  // namespace
}  // namespace anchorbench::estimator
