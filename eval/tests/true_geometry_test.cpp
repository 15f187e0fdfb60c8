// The PDOP estimates against the truth: Theorem 3.1's bound, the true PDOP and the bias-aware DOP.
#include "anchorbench/eval/true_geometry.hpp"

#include <cmath>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "anchorbench/estimator/closest_point_pdop.hpp"
#include "anchorbench/estimator/pdop.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::eval {
namespace {

using estimator::ClosestPointPdop;
using estimator::GeometryPdop;

// Theorem 3.1 claims: if ||p_k - p_C|| <= ||p_k - p_A|| for all k, the closest-point PDOP (with
// the true distances as d_k) is >= the true PDOP. The proof's step from "every row of G~ is no
// longer than the matching row of G" to "G~^T G~ <= G^T G" ignores that the rows point in
// different directions, and the claim fails. Anchor at the origin, five tags (integers, metres);
// p_C = (-4,-1,1) (range sqrt(18)); ||p_k - p_C|| = 5, 1, sqrt(26), 0, sqrt(38) against ranges
// sqrt(53), sqrt(21), sqrt(26), sqrt(18), sqrt(38): the precondition holds, yet the estimate
// (4.596) is below the true PDOP (6.548).
TEST(ClosestPointPdop, Theorem31CounterexampleSatisfiesPreconditionYetUnderestimates) {
  const std::vector<Eigen::Vector3d> p = {{-4, -1, 6}, {-4, -2, 1}, {-1, 0, 5}, {-4, -1, 1}, {-3, -2, -5}};
  const Eigen::Vector3d p_anchor = Eigen::Vector3d::Zero();
  ClosestPointPdop estimate;
  for (const auto& tag : p) {
    EXPECT_LE((tag - Eigen::Vector3d(-4, -1, 1)).norm(), tag.norm() + 1e-12);  // precondition
    estimate.Add(tag, tag.norm());
  }
  EXPECT_EQ(estimate.p_world_closest(), Eigen::Vector3d(-4, -1, 1));
  EXPECT_NEAR(estimate.Value(), 4.596, 1e-3);
  EXPECT_NEAR(TruePdop(p, p_anchor), 6.548, 1e-3);
}

// What does hold, measured over random geometries that meet the precondition: the bound holds
// in about 97% of them (3.3% violations over 15k geometries, worst ratio 0.73).
TEST(ClosestPointPdop, Theorem31BoundHoldsOnMostGeometriesMeetingThePrecondition) {
  int checked = 0, violations = 0;
  double worst_ratio = 1.0;
  for (int trial = 0; trial < 3000; ++trial) {
    auto rng = testing::TestStream(1000 + trial);
    const Eigen::Vector3d p_anchor = testing::UniformIn(rng, Eigen::Vector3d(-5, -5, 0), Eigen::Vector3d(5, 5, 6));
    const int n = 5 + static_cast<int>(rng.Uniform() * 60);
    const Eigen::Vector3d center = testing::UniformIn(rng, Eigen::Vector3d(-10, -10, 0), Eigen::Vector3d(10, 10, 3));
    const double spread = rng.Uniform(0.5, 6.0);
    std::vector<Eigen::Vector3d> p;
    std::vector<double> d;
    for (int k = 0; k < n; ++k) {
      p.push_back(center + spread * testing::UniformIn(rng, -Eigen::Vector3d::Ones(), Eigen::Vector3d::Ones()));
      d.push_back((p.back() - p_anchor).norm());
    }
    std::size_t j = 0;
    for (int k = 1; k < n; ++k)
      if (d[k] < d[j]) j = k;
    bool precondition = true;
    for (int k = 0; k < n; ++k) precondition &= (p[k] - p[j]).norm() <= d[k];
    const double truth = TruePdop(p, p_anchor);
    if (!precondition || std::isinf(truth)) continue;
    ClosestPointPdop estimate;
    for (int k = 0; k < n; ++k) estimate.Add(p[k], d[k]);
    ++checked;
    const double ratio = estimate.Value() / truth;
    if (ratio < 1.0) ++violations;
    worst_ratio = std::min(worst_ratio, ratio);
  }
  ASSERT_GT(checked, 2000);
  EXPECT_LT(violations, 0.05 * checked);
  EXPECT_GT(worst_ratio, 0.6);
}

TEST(Pdop, GeometryPdopWithTrueDistancesIsTruePdop) {
  auto rng = testing::TestStream(7);
  const auto data = testing::BoxData(rng, 50, Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(8, 0, 1), 5.0, 0.0, 0.0);
  EXPECT_NEAR(GeometryPdop(data.p_world_tag, data.range_m, data.p_world_anchor),
              TruePdop(data.p_world_tag, data.p_world_anchor), 1e-12);
}

// DOP^2 = HDOP^2 + VDOP^2 for the bias-aware DOP; a nearly flat path below the anchor sees the
// height, traded off against the bias, far worse than x-y; a path with height change much less so.
TEST(Pdop, BiasAwareHorizontalAndVerticalPartsAddUp) {
  auto rng = testing::TestStream(5);
  const Eigen::Vector3d p_anchor(1.0, 2.0, 8.0);
  TrueGeometry flat(p_anchor), varied(p_anchor);
  EXPECT_TRUE(std::isinf(flat.BiasAwareHorizontalDop()) && std::isinf(flat.BiasAwareVerticalDop()));
  for (int k = 0; k < 200; ++k) {
    // A ring 18-22 m around the anchor: on flat ground every row has nearly the same vertical part.
    const double angle = rng.Uniform(0.0, 6.283), radius = rng.Uniform(18.0, 22.0);
    const Eigen::Vector3d around(p_anchor.x() + radius * std::cos(angle), p_anchor.y() + radius * std::sin(angle), 0.0);
    flat.Add(around + Eigen::Vector3d(0, 0, rng.Uniform(0.0, 0.05)));
    varied.Add(around + Eigen::Vector3d(0, 0, rng.Uniform(0.0, 6.0)));
  }
  const double h = flat.BiasAwareHorizontalDop(), v = flat.BiasAwareVerticalDop();
  const double dop = flat.BiasAwareDop();
  EXPECT_NEAR(h * h + v * v, dop * dop, 1e-9 * dop * dop);
  EXPECT_GT(v, 3.0 * h);
  EXPECT_LT(varied.BiasAwareVerticalDop(), 0.5 * v);
}

TEST(Pdop, OrthogonalUnitDirectionsGiveSqrtThree) {
  // Three orthogonal unit rows: G^T G = I, so PDOP = sqrt(tr(I)) = sqrt(3).
  const std::vector<Eigen::Vector3d> p = {{5, 0, 0}, {0, 5, 0}, {0, 0, 5}};
  EXPECT_NEAR(TruePdop(p, Eigen::Vector3d::Zero()), std::sqrt(3.0), 1e-12);
}

TEST(Pdop, BiasAwareDopIsPositionBlockOfFourParameterInverse) {
  auto rng = testing::TestStream(8);
  const auto data = testing::BoxData(rng, 60, Eigen::Vector3d(0, 0, 3), Eigen::Vector3d(6, 1, 1), 4.0, 0.0, 0.0);
  Eigen::Matrix4d information = Eigen::Matrix4d::Zero();
  for (const auto& p : data.p_world_tag) {
    Eigen::Vector4d h;
    h << (p - data.p_world_anchor).normalized(), 1.0;  // H = [G | 1]
    information += h * h.transpose();
  }
  const double direct = std::sqrt(information.inverse().topLeftCorner<3, 3>().trace());
  const double bias_aware = BiasAwareDop(data.p_world_tag, data.p_world_anchor);
  EXPECT_NEAR(bias_aware, direct, 1e-9 * direct);
  EXPECT_GE(bias_aware, TruePdop(data.p_world_tag, data.p_world_anchor));
}

}  // namespace
}  // namespace anchorbench::eval
