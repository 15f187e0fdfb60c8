// Every enum's names table, as the config reads and writes it: each name parses back to its
// value, names are distinct, and an unknown name leaves the value alone.
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "anchorbench/estimator/anchor_initializer.hpp"
#include "anchorbench/estimator/ransac_solver.hpp"
#include "anchorbench/sim/scenario.hpp"

namespace anchorbench {
namespace {

template <typename Enum, std::size_t N>
void ExpectRoundTrips(const estimator::EnumNames<Enum, N>& names, std::initializer_list<Enum> values) {
  std::set<std::string> seen;
  for (Enum value : values) {
    Enum parsed{};
    ASSERT_TRUE(names.Parse(names.Name(value), &parsed)) << names.Name(value);
    EXPECT_EQ(parsed, value);
    EXPECT_TRUE(seen.insert(std::string(names.Name(value))).second) << names.Name(value);
  }
  EXPECT_EQ(seen.size(), N);
  Enum untouched = *values.begin();
  EXPECT_FALSE(names.Parse("no_such_name", &untouched));
  EXPECT_EQ(untouched, *values.begin());
}

TEST(EnumNames, EveryTableRoundTrips) {
  using namespace estimator;
  ExpectRoundTrips(kKernelModeNames, {KernelMode::kL2, KernelMode::kAdaptive, KernelMode::kFixed});
  ExpectRoundTrips(kBufferPolicyNames, {BufferPolicy::kThin, BufferPolicy::kKeepFirst});
  ExpectRoundTrips(kRansacSchemeNames, {RansacScheme::kMinimal, RansacScheme::kFullSolve});
  ExpectRoundTrips(kLsPivotNames, {LsPivot::kShortestRange, LsPivot::kMinimumVariance});
  ExpectRoundTrips(kLsMethodNames, {LsMethod::kOrdinary, LsMethod::kTotal});
  ExpectRoundTrips(kSideNames, {HeightCheckOptions::Side::kAny, HeightCheckOptions::Side::kAbove,
                                HeightCheckOptions::Side::kBelow});
  ExpectRoundTrips(kSolveStatusNames,
                   {SolveStatus::kConverged, SolveStatus::kMaxIterations, SolveStatus::kNoConvergence,
                    SolveStatus::kTooFewSamples, SolveStatus::kDegenerateGeometry, SolveStatus::kNumericalFailure,
                    SolveStatus::kHeightUnobservable, SolveStatus::kBudgetSpent});
  ExpectRoundTrips(sim::kHallWallsNames, {sim::HallWalls::kAll, sim::HallWalls::kFront});
  ExpectRoundTrips(sim::kBiasDistributionNames, {sim::BiasDistribution::kUniform, sim::BiasDistribution::kNormal});
  ExpectRoundTrips(sim::kOutlierKindNames, {sim::OutlierKind::kPositive, sim::OutlierKind::kSymmetric});
  ExpectRoundTrips(sim::kTrajectoryKindNames, {sim::TrajectoryKind::kRandom, sim::TrajectoryKind::kStraight,
                                               sim::TrajectoryKind::kPlanar, sim::TrajectoryKind::kShort,
                                               sim::TrajectoryKind::kApproach});
  ExpectRoundTrips(sim::kEnvironmentKindNames, {sim::EnvironmentKind::kTunnel, sim::EnvironmentKind::kHall});
  EXPECT_EQ(kKernelModeNames.Choices(), "adaptive, l2, fixed");
}

}  // namespace
}  // namespace anchorbench
