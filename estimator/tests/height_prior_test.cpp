// A known anchor height: on a flat path, where the ranges leave the height to a mirror ambiguity,
// the prior gives x-y from the ranges and z from itself; where the ranges observe the height, a
// loose prior changes nothing and a tight one wins; the covariance carries the prior.
#include "anchorbench/estimator/height_prior.hpp"

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/closest_point_pdop.hpp"
#include "anchorbench/estimator/height_check.hpp"
#include "anchorbench/estimator/ls_solver.hpp"
#include "anchorbench/estimator/scaled_solver.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::estimator {
namespace {

const Eigen::Vector3d kPriorAnchor(3.0, 4.0, 4.5);
constexpr double kBiasM = 0.2;

// A tag weaving in x-y at 1.5 m with a vertical wobble of `wobble_m` (0: exactly flat), noise 0.05 m.
testing::AnchorData Path(double wobble_m, std::uint64_t seed) {
  return testing::WeavingData(kPriorAnchor, kBiasM, wobble_m, 0.05, seed);
}

AnchorSolverOptions Options(std::optional<HeightPrior> prior) {
  AnchorSolverOptions options;
  options.nls.kernel_scale_m = 0.05;
  options.height_prior = prior;
  return options;
}

TEST(HeightPrior, OnAnExactlyFlatPathTheLsNeedsItAndGetsXyFromTheRanges) {
  const testing::AnchorData flat = Path(0.0, 1);
  EXPECT_EQ(SolveDoubleDifferenceLs(flat.p_world_tag, flat.range_m).status, SolveStatus::kDegenerateGeometry);
  const SolveResult ls = SolveDoubleDifferenceLs(flat.p_world_tag, flat.range_m, {}, HeightPrior{kPriorAnchor.z(), 0.1});
  ASSERT_TRUE(Succeeded(ls.status)) << ToString(ls.status);
  EXPECT_LT((ls.p_world_anchor - kPriorAnchor).head<2>().norm(), 0.3);
  EXPECT_NEAR(ls.p_world_anchor.z(), kPriorAnchor.z(), 0.3);
}

TEST(HeightPrior, FlatPathsInitializeOnTheRightSideWithXyFromTheRanges) {
  for (std::uint64_t seed : {1, 2, 3}) {  // seed 2 converges to the mirror without a prior
    const testing::AnchorData flat = Path(0.003, seed);
    const SolveResult with = AnchorSolver(Options(HeightPrior{kPriorAnchor.z(), 0.1})).Solve(flat.p_world_tag, flat.range_m);
    ASSERT_TRUE(Succeeded(with.status)) << "seed " << seed;
    EXPECT_LT((with.p_world_anchor - kPriorAnchor).head<2>().norm(), 0.1) << "seed " << seed;
    EXPECT_NEAR(with.p_world_anchor.z(), kPriorAnchor.z(), 0.2) << "seed " << seed;
    EXPECT_NEAR(with.bias_m, kBiasM, 0.1) << "seed " << seed;
    // The height's standard deviation is the prior's at most (the ranges add a little).
    EXPECT_LE(std::sqrt(with.covariance(2, 2)), 0.1 + 1e-9) << "seed " << seed;
    EXPECT_GT(std::sqrt(with.covariance(2, 2)), 0.01) << "seed " << seed;
  }
  const testing::AnchorData mirrored = Path(0.003, 2);
  EXPECT_LT(AnchorSolver(Options(std::nullopt)).Solve(mirrored.p_world_tag, mirrored.range_m).p_world_anchor.z(), 1.5);
}

// A flat path still observes how far the anchor is from the path's plane, only not on which side:
// a prior 1 m off but on the right side is mostly overruled by the ranges, one on the wrong side
// (the mirror's height) puts the anchor there.
TEST(HeightPrior, OnAFlatPathThePriorPicksTheSideAndTheRangesTheDistance) {
  const testing::AnchorData flat = Path(0.003, 1);
  const SolveResult off =
      AnchorSolver(Options(HeightPrior{kPriorAnchor.z() + 1.0, 0.05})).Solve(flat.p_world_tag, flat.range_m);
  ASSERT_TRUE(Succeeded(off.status));
  EXPECT_LT(std::abs(off.p_world_anchor.z() - kPriorAnchor.z()), 0.3);
  EXPECT_LT((off.p_world_anchor - kPriorAnchor).head<2>().norm(), 0.1);
  const double mirror_z = 1.5 - (kPriorAnchor.z() - 1.5);
  const SolveResult mirrored =
      AnchorSolver(Options(HeightPrior{mirror_z, 0.5})).Solve(flat.p_world_tag, flat.range_m);
  ASSERT_TRUE(Succeeded(mirrored.status));
  EXPECT_NEAR(mirrored.p_world_anchor.z(), mirror_z, 0.3);
  EXPECT_LT((mirrored.p_world_anchor - kPriorAnchor).head<2>().norm(), 0.1);  // x-y survive a wrong side
}

// Where the ranges observe the height, a loose prior (10 m) changes the estimate by a hair, and a
// tight wrong one (1 m off, 1 mm) moves it to the prior's height.
TEST(HeightPrior, WhereTheRangesSeeTheHeightTheyAreWeighedAgainstIt) {
  const testing::AnchorData varied = Path(1.0, 4);
  const SolveResult none = AnchorSolver(Options(std::nullopt)).Solve(varied.p_world_tag, varied.range_m);
  const SolveResult loose =
      AnchorSolver(Options(HeightPrior{kPriorAnchor.z() + 1.0, 10.0})).Solve(varied.p_world_tag, varied.range_m);
  const SolveResult tight =
      AnchorSolver(Options(HeightPrior{kPriorAnchor.z() + 1.0, 0.001})).Solve(varied.p_world_tag, varied.range_m);
  ASSERT_TRUE(Succeeded(none.status) && Succeeded(loose.status) && Succeeded(tight.status));
  EXPECT_LT((none.p_world_anchor - kPriorAnchor).norm(), 0.1);
  EXPECT_LT((loose.p_world_anchor - none.p_world_anchor).norm(), 0.01);
  EXPECT_NEAR(tight.p_world_anchor.z(), kPriorAnchor.z() + 1.0, 0.01);
  EXPECT_LT(std::sqrt(loose.covariance(2, 2)), 10.0 * 0.01);  // the ranges' information dominates
}

// The mirror check weighs the prior too: on a flat path with a prior it accepts the estimate.
TEST(HeightPrior, TheMirrorCheckCountsThePrior) {
  const testing::AnchorData flat = Path(0.003, 2);
  const HeightPrior prior{kPriorAnchor.z(), 0.1};
  const HeightCheckOptions check;
  EXPECT_EQ(HeightCheckedSolver(std::make_shared<AnchorSolver>(Options(std::nullopt)), check)
                .Solve(flat.p_world_tag, flat.range_m)
                .status,
            SolveStatus::kHeightUnobservable);
  // The check reads the prior from the solver it wraps, through any decorator between them.
  auto solver = std::make_shared<ScaledSolver>(std::make_shared<AnchorSolver>(Options(prior)), ScaleOptions{});
  ASSERT_TRUE(solver->height_prior().has_value());
  const SolveResult checked = HeightCheckedSolver(solver, check).Solve(flat.p_world_tag, flat.range_m);
  ASSERT_TRUE(Succeeded(checked.status)) << ToString(checked.status);
  EXPECT_LT((checked.p_world_anchor - kPriorAnchor).norm(), 0.2);
}

// The closest-point DOP of x-y: finite on an exactly flat path, where the 3-D one is not, and
// never above the 3-D one where that is finite (a block's inverse is below the inverse's block).
TEST(HeightPrior, HorizontalClosestPointDopIsFiniteOnAFlatPath) {
  const testing::AnchorData flat = Path(0.0, 1);
  const testing::AnchorData varied = Path(1.0, 1);
  ClosestPointPdop flat_dop, varied_dop;
  for (std::size_t k = 0; k < flat.range_m.size(); ++k) {
    flat_dop.Add(flat.p_world_tag[k], flat.range_m[k]);
    varied_dop.Add(varied.p_world_tag[k], varied.range_m[k]);
    if (k >= 3) {
      EXPECT_LE(varied_dop.HorizontalValue(), varied_dop.Value() * (1.0 + 1e-12));
    }
  }
  EXPECT_TRUE(std::isinf(flat_dop.Value()));
  EXPECT_TRUE(std::isfinite(flat_dop.HorizontalValue()));
  EXPECT_LT(flat_dop.HorizontalValue(), 1.0);
  EXPECT_TRUE(std::isinf(ClosestPointPdop().HorizontalValue()));
}

TEST(HeightPrior, Validation) {
  std::string why;
  EXPECT_TRUE((HeightPrior{2.0, 0.1}.IsValid(&why)));
  EXPECT_FALSE((HeightPrior{2.0, 0.0}.IsValid(&why)));
  EXPECT_FALSE((HeightPrior{std::nan(""), 0.1}.IsValid(&why)));
  EXPECT_NE(why.find("sigma_m"), std::string::npos);
  EXPECT_DOUBLE_EQ((HeightPrior{2.0, 0.5}.Chi2(3.0)), 4.0);
}

}  // namespace
}  // namespace anchorbench::estimator
