// The credibility measures: NEES of one attempt, ANEES with its chi-square bounds over many. On
// clean data with the noise the L2 solver assumes, its covariances must pass the test they are
// reported against; a covariance scaled down must fail it.
#include "anchorbench/eval/credibility.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/eval/attempt_evaluation.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::eval {
namespace {

TEST(Credibility, NeesIsTheMahalanobisSquareAndAbsentWithoutAPositiveDefiniteCovariance) {
  const Eigen::Vector3d error(0.2, -0.1, 0.3);
  const Eigen::Matrix3d covariance = Eigen::Vector3d(0.04, 0.01, 0.09).asDiagonal();
  EXPECT_NEAR(*Nees(error, covariance), 1.0 + 1.0 + 1.0, 1e-12);
  EXPECT_FALSE(Nees(error, Eigen::Matrix3d::Zero()));
  Eigen::Matrix3d indefinite = covariance;
  indefinite(2, 2) = -0.09;
  EXPECT_FALSE(Nees(error, indefinite));
}

TEST(Credibility, BoundsAndQuantilesMatchTheChiSquareTables) {
  EXPECT_NEAR(ChiSquare95(3), 7.8147, 1e-4);
  // 100 runs of 3 dof: the sum is chi-square with 300 dof, whose 2.5% / 97.5% points are
  // 253.9 and 349.9 (tables), so the ANEES bounds are 2.539 and 3.499.
  const auto [lo, hi] = AneesBounds(100, 3);
  EXPECT_NEAR(lo, 2.539, 0.005);
  EXPECT_NEAR(hi, 3.499, 0.005);
  const Credibility none = CredibilityOf({}, 3);
  EXPECT_EQ(none.n, 0);
  EXPECT_FALSE(none.anees);
}

// Many noise realizations of one clean geometry, solved by lm_l2, evaluated as a run would be.
std::vector<double> PositionNees(double covariance_scale) {
  constexpr int kRuns = 400;
  const schema::AnchorTruth truth{Eigen::Vector3d(2, -1, 3), 0.2};
  constexpr double kSigma = 0.1;
  estimator::AnchorSolverOptions options;
  options.nls.kernel = estimator::KernelMode::kL2;
  options.nls.kernel_scale_m = kSigma;
  options.nls.step_tolerance_m = 1e-6;
  const estimator::AnchorSolver solver(options);
  std::vector<double> nees;
  for (int run = 0; run < kRuns; ++run) {
    auto geometry = testing::TestStream(7);
    auto noise = testing::TestStream(20000 + run);
    auto data = testing::BoxData(geometry, 150, truth.p_world_anchor, Eigen::Vector3d(6, 2, 1), 5.0, *truth.bias_m, 0.0);
    for (double& d : data.range_m) d += kSigma * noise.Normal();
    estimator::SolveResult result = solver.Solve(data.p_world_tag, data.range_m);
    result.covariance *= covariance_scale;
    const schema::AttemptEvaluation e = Evaluate(data.p_world_tag, &result, truth);
    nees.push_back(*e.nees_position);
  }
  return nees;
}

TEST(Credibility, L2CovariancesOnCleanDataAreCredibleAndShrunkOnesAreNot) {
  const Credibility credible = CredibilityOf(PositionNees(1.0), 3);
  EXPECT_GT(*credible.anees, *credible.bound_lo);
  EXPECT_LT(*credible.anees, *credible.bound_hi);
  EXPECT_NEAR(*credible.above_95_pct, 5.0, 3.0);  // binomial sd of 400 draws at 5%: 1.1 points
  const Credibility over_confident = CredibilityOf(PositionNees(0.5), 3);  // variances halved
  EXPECT_GT(*over_confident.anees, *over_confident.bound_hi);
}

}  // namespace
}  // namespace anchorbench::eval
