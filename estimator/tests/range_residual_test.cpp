// The one range residual of Eq. (11) and its Jacobian, against central differences (as Sophus and
// manif test their Jacobians: many random points).
#include "anchorbench/estimator/range_residual.hpp"

#include <gtest/gtest.h>

#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::estimator {
namespace {

TEST(RangeResidual, JacobianMatchesCentralDifferences) {
  auto rng = testing::TestStream(41);
  for (int trial = 0; trial < 500; ++trial) {
    const double bias_m = rng.Uniform(-1, 1);
    const Eigen::Vector3d p_anchor = testing::UniformIn(rng, Eigen::Vector3d(-20, -20, 0), Eigen::Vector3d(20, 20, 6));
    const Eigen::Vector4d theta(p_anchor.x(), p_anchor.y(), p_anchor.z(), bias_m);
    const Eigen::Vector3d p_tag = testing::UniformIn(rng, Eigen::Vector3d(-20, -20, 0), Eigen::Vector3d(20, 20, 3));
    if ((theta.head<3>() - p_tag).norm() < 0.5) continue;  // the direction is ill-defined at the tag
    const double range_m = rng.Uniform(0.5, 40.0);
    Eigen::Vector4d jacobian;
    const double r = RangeResidual(theta, p_tag, range_m, &jacobian);
    EXPECT_DOUBLE_EQ(r, RangeResidual(theta.head<3>(), theta(3), p_tag, range_m));
    for (int i = 0; i < 4; ++i) {
      constexpr double h = 1e-6;
      Eigen::Vector4d up = theta, down = theta;
      up(i) += h;
      down(i) -= h;
      Eigen::Vector4d ignored;
      const double numeric = (RangeResidual(up, p_tag, range_m, &ignored) - RangeResidual(down, p_tag, range_m, &ignored)) / (2 * h);
      EXPECT_NEAR(jacobian(i), numeric, 1e-7) << "trial " << trial << " parameter " << i;
    }
  }
}

TEST(RangeResidual, WorkedByHand) {
  // Anchor (3, 4, 0) with bias 0.5, tag at the origin, measured 6: r = 5 + 0.5 - 6 = -0.5,
  // row [0.6, 0.8, 0, 1] (the unit vector from the tag to the anchor, then the bias).
  Eigen::Vector4d jacobian;
  EXPECT_DOUBLE_EQ(RangeResidual(Eigen::Vector4d(3, 4, 0, 0.5), Eigen::Vector3d::Zero(), 6.0, &jacobian), -0.5);
  EXPECT_TRUE(jacobian.isApprox(Eigen::Vector4d(0.6, 0.8, 0.0, 1.0)));
  // On the tag: no direction, a zero position row, never NaN.
  RangeResidual(Eigen::Vector4d(1, 1, 1, 0), Eigen::Vector3d(1, 1, 1), 2.0, &jacobian);
  EXPECT_EQ(jacobian, Eigen::Vector4d(0, 0, 0, 1));
}

}  // namespace
}  // namespace anchorbench::estimator
