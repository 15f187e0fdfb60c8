// The exploration study's body (studies/src/exploration/exploration_body.hpp): detours chain without the
// return between them, and a dwell can be cut short.
#include "exploration_body.hpp"

#include <vector>

#include <gtest/gtest.h>

namespace anchorbench::studies {
namespace {

// A straight pattern along x, 0.1 m a step, and a body that moves 0.5 m a step off it.
std::vector<Eigen::Vector3d> Line() {
  std::vector<Eigen::Vector3d> pattern;
  for (int i = 0; i <= 100; ++i) pattern.emplace_back(0.1 * i, 0.0, 1.0);
  return pattern;
}

TEST(ExplorationBody, AfterItsDwellTheBodyIsFreeOnTheWayBackAndANewRouteStartsThere) {
  const std::vector<Eigen::Vector3d> pattern = Line();
  Body body(pattern, 0.5);
  body.Visit({Eigen::Vector3d(0.0, 2.0, 1.0)}, 2);
  EXPECT_FALSE(body.free());
  for (int k = 0; k < 4; ++k) body.Step();  // 4 steps out: there
  EXPECT_TRUE(body.dwelling());
  body.Step();
  body.Step();  // the dwell's 2 epochs
  ASSERT_TRUE(body.free());
  EXPECT_FALSE(body.on_pattern());  // on the way back
  // The next detour from there: straight on, not back to the pattern first.
  body.Visit({Eigen::Vector3d(1.0, 2.0, 1.0)}, 1);
  body.Step();
  body.Step();
  EXPECT_TRUE(body.dwelling());
  EXPECT_TRUE(body.p_world_body().isApprox(Eigen::Vector3d(1.0, 2.0, 1.0)));
  EXPECT_NEAR(body.distance_m(), 3.0, 1e-12);  // 2 m out, 1 m across
}

TEST(ExplorationBody, LeaveCutsTheDwellShortAndReturnsToWhereThePatternWasLeft) {
  const std::vector<Eigen::Vector3d> pattern = Line();
  Body body(pattern, 0.5);
  for (int k = 0; k < 10; ++k) body.Step();  // 1 m along the pattern
  body.Visit({Eigen::Vector3d(1.0, 1.0, 1.0)}, 50);
  body.Step();
  body.Step();
  ASSERT_TRUE(body.dwelling());
  body.Leave();
  EXPECT_TRUE(body.free());
  body.Step();
  body.Step();
  EXPECT_TRUE(body.on_pattern());
  EXPECT_TRUE(body.p_world_body().isApprox(Eigen::Vector3d(1.0, 0.0, 1.0)));
}

}  // namespace
}  // namespace anchorbench::studies
