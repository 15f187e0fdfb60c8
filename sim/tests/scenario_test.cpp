#include "anchorbench/sim/scenario.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace anchorbench::sim {
namespace {

ScenarioOptions TunnelScenario() {
  ScenarioOptions o;
  o.tunnel.length_m = 120.0;
  o.tunnel.num_anchors = 12;
  o.ranging.sigma_range_m = 0.1;
  o.ranging.outlier_probability = 0.1;
  o.ranging.sigma_position_m = 0.02;
  return o;
}

TEST(Scenario, DeterministicInSeedAndRealization) {
  const ScenarioOptions o = TunnelScenario();
  const Scenario a = GenerateScenario(o, 1, 2), b = GenerateScenario(o, 1, 2), c = GenerateScenario(o, 1, 3);
  ASSERT_EQ(a.ranges.size(), b.ranges.size());
  for (std::size_t i = 0; i < a.ranges.size(); ++i) EXPECT_EQ(a.ranges[i].range_m, b.ranges[i].range_m);
  EXPECT_NE(a.anchors[0].p_world_anchor, c.anchors[0].p_world_anchor);
}

TEST(Scenario, TunnelAnchorsSpanTheLengthOnWallsAndCeiling) {
  const ScenarioOptions o = TunnelScenario();
  const Scenario s = GenerateScenario(o, 5, 0);
  ASSERT_EQ(s.anchors.size(), 12u);
  double min_x = 1e9, max_x = -1e9;
  for (const SimAnchor& a : s.anchors) {
    const Eigen::Vector3d& p = a.p_world_anchor;
    min_x = std::min(min_x, p.x());
    max_x = std::max(max_x, p.x());
    const bool on_wall = std::abs(std::abs(p.y()) - 0.5 * o.tunnel.width_m) < 1e-12 &&
                         p.z() >= o.tunnel.anchor_height_min_m && p.z() <= o.tunnel.anchor_height_max_m;
    const bool on_ceiling = p.z() == o.tunnel.height_m;
    EXPECT_TRUE(on_wall || on_ceiling);
    EXPECT_GE(a.bias_m, o.ranging.bias_a_m);
    EXPECT_LE(a.bias_m, o.ranging.bias_b_m);
  }
  EXPECT_LT(min_x, 0.15 * o.tunnel.length_m);
  EXPECT_GT(max_x, 0.85 * o.tunnel.length_m);
}

TEST(Scenario, RangesFollowEq1WithinMaxRangeAndOutlierRate) {
  ScenarioOptions o = TunnelScenario();
  const Scenario s = GenerateScenario(o, 9, 0);
  ASSERT_GT(s.ranges.size(), 1000u);
  int outliers = 0;
  double sum_sq = 0.0;
  int inliers = 0;
  std::size_t epoch = 0;
  for (const SimRange& r : s.ranges) {
    while (s.t_s[epoch] < r.t_s) ++epoch;
    const SimAnchor& a = s.anchors[r.anchor_id];
    const double distance = (s.p_world_tag_true[0][epoch] - a.p_world_anchor).norm();
    EXPECT_LE(distance, o.ranging.max_range_m);
    EXPECT_GE(r.range_m, 0.0);
    if (r.is_outlier) {
      ++outliers;
      EXPECT_GE(r.range_m - distance - a.bias_m, o.ranging.outlier_min_m - 1.0);  // positive, NLOS-like
    } else {
      const double noise = r.range_m - distance - a.bias_m;
      sum_sq += noise * noise;
      ++inliers;
    }
  }
  const double rate = static_cast<double>(outliers) / s.ranges.size();
  EXPECT_NEAR(rate, 0.1, 0.02);
  EXPECT_NEAR(std::sqrt(sum_sq / inliers), 0.1, 0.01);
}

TEST(Scenario, OutlierEpisodesHaveTheirMeanLengthAndRate) {
  ScenarioOptions o = TunnelScenario();
  o.ranging.outlier_probability = 0.1;
  o.ranging.outlier_burst_length = 20.0;
  o.ranging.max_range_m = 1000.0;  // every anchor every epoch: episodes are runs in one anchor's sequence
  const Scenario s = GenerateScenario(o, 2, 0);
  std::vector<int> run(s.anchors.size(), 0);
  std::vector<double> offset(s.anchors.size(), 0.0);
  int outliers = 0, episodes = 0;
  std::size_t epoch = 0;
  for (const SimRange& r : s.ranges) {
    while (s.t_s[epoch] < r.t_s) ++epoch;
    if (r.is_outlier) {
      ++outliers;
      const double excess = r.range_m - (s.p_world_tag_true[0][epoch] - s.anchors[r.anchor_id].p_world_anchor).norm() -
                            s.anchors[r.anchor_id].bias_m;
      if (run[r.anchor_id] == 0) {
        ++episodes;
        offset[r.anchor_id] = excess;
      } else {
        EXPECT_NEAR(excess, offset[r.anchor_id], 1.0);  // one offset per episode (plus noise)
      }
      ++run[r.anchor_id];
    } else {
      run[r.anchor_id] = 0;
    }
  }
  const double rate = static_cast<double>(outliers) / s.ranges.size();
  // ~25k ranges in ~125 episodes: the rate's standard error is ~0.009, the mean length's ~2.
  EXPECT_NEAR(rate, 0.1, 0.03);
  EXPECT_NEAR(static_cast<double>(outliers) / episodes, 20.0, 6.0);
}

TEST(Scenario, IllConditionedTrajectoriesAreWhatTheySay) {
  ScenarioOptions o = TunnelScenario();
  o.trajectory.kind = TrajectoryKind::kStraight;
  const Scenario straight = GenerateScenario(o, 3, 0);
  for (const auto& p : straight.p_world_tag_true[0]) {
    EXPECT_EQ(p.y(), straight.p_world_tag_true[0][0].y());
    EXPECT_EQ(p.z(), o.trajectory.height_m);
  }
  o.trajectory.kind = TrajectoryKind::kPlanar;
  const Scenario planar = GenerateScenario(o, 3, 0);
  double y_span = 0.0;
  for (const auto& p : planar.p_world_tag_true[0]) {
    EXPECT_EQ(p.z(), o.trajectory.height_m);
    y_span = std::max(y_span, std::abs(p.y()));
  }
  EXPECT_GT(y_span, 0.5);
  o.trajectory.kind = TrajectoryKind::kShort;
  const Scenario short_run = GenerateScenario(o, 3, 0);
  const double covered = short_run.p_world_tag_true[0].back().x() - short_run.p_world_tag_true[0].front().x();
  EXPECT_NEAR(covered, o.trajectory.short_fraction * o.tunnel.length_m, 1.0);
}

TEST(Scenario, TrajectoryKindMixFollowsTheFractions) {
  ScenarioOptions o = TunnelScenario();
  o.trajectory.fraction_straight = 0.2;
  o.trajectory.fraction_planar = 0.3;
  int straight = 0, planar = 0, random = 0;
  for (int r = 0; r < 1000; ++r) {
    RandomStream rng(1, r, StreamId::kTrajectory);
    switch (DrawTrajectoryKind(o.trajectory, rng)) {
      case TrajectoryKind::kStraight: ++straight; break;
      case TrajectoryKind::kPlanar: ++planar; break;
      case TrajectoryKind::kRandom: ++random; break;
      default: FAIL();
    }
  }
  // Binomial standard errors: 13 and 14.5 of 1000.
  EXPECT_NEAR(straight, 200, 45);
  EXPECT_NEAR(planar, 300, 45);
  EXPECT_NEAR(random, 500, 50);
}

TEST(Scenario, TrajectoryStaysInsideTheTunnel) {
  const ScenarioOptions o = TunnelScenario();
  const Scenario s = GenerateScenario(o, 11, 0);
  for (const auto& p : s.p_world_tag_true[0]) {
    EXPECT_LE(std::abs(p.y()), 0.5 * o.tunnel.width_m);
    EXPECT_GE(p.z(), 0.0);
    EXPECT_LE(p.z(), o.tunnel.height_m);
  }
  EXPECT_NEAR(s.t_s[1] - s.t_s[0], 0.1, 1e-12);  // 10 Hz default
}

TEST(Scenario, HallAnchorsOnWalls) {
  ScenarioOptions o;
  o.environment = EnvironmentKind::kHall;
  const Scenario s = GenerateScenario(o, 1, 0);
  ASSERT_EQ(s.anchors.size(), static_cast<std::size_t>(o.hall.num_anchors));
  for (const SimAnchor& a : s.anchors) {
    const Eigen::Vector3d& p = a.p_world_anchor;
    const bool on_wall = std::abs(p.x()) < 1e-9 || std::abs(p.x() - o.hall.length_m) < 1e-9 ||
                         std::abs(p.y()) < 1e-9 || std::abs(p.y() - o.hall.width_m) < 1e-9;
    EXPECT_TRUE(on_wall) << p.transpose();
  }
}

TEST(Scenario, TwoTagsAtRigidOffsetsAcrossTheDirectionOfTravel) {
  ScenarioOptions o = TunnelScenario();
  o.tag_offsets_m = {Eigen::Vector3d(0, 0.425, 0), Eigen::Vector3d(0, -0.425, 0)};  // 0.85 m apart, left/right
  const Scenario s = GenerateScenario(o, 4, 0);
  ASSERT_EQ(s.p_world_tag_true.size(), 2u);
  for (std::size_t k = 1; k + 1 < s.t_s.size(); k += 50) {
    const Eigen::Vector3d baseline = s.p_world_tag_true[0][k] - s.p_world_tag_true[1][k];
    EXPECT_NEAR(baseline.norm(), 0.85, 1e-9);
    const Eigen::Vector3d travel = s.p_world_body[k + 1] - s.p_world_body[k - 1];
    EXPECT_NEAR(baseline.head<2>().dot(travel.head<2>()), 0.0, 1e-9);  // across the direction of travel
    EXPECT_GT(travel.x() * baseline.y() - travel.y() * baseline.x(), 0.0);  // tag 0 on the left
  }
  int from_tag1 = 0;
  for (const SimRange& r : s.ranges) from_tag1 += r.tag_id == 1;
  EXPECT_NEAR(from_tag1, static_cast<double>(s.ranges.size()) / 2, 0.05 * s.ranges.size());
  // Adding a tag leaves tag 0's ranges as they were for a single-tag robot.
  ScenarioOptions single = TunnelScenario();
  single.tag_offsets_m = {Eigen::Vector3d(0, 0.425, 0)};
  const Scenario one = GenerateScenario(single, 4, 0);
  std::vector<double> tag0;
  for (const SimRange& r : s.ranges)
    if (r.tag_id == 0) tag0.push_back(r.range_m);
  ASSERT_EQ(tag0.size(), one.ranges.size());
  for (std::size_t i = 0; i < tag0.size(); ++i) EXPECT_EQ(tag0[i], one.ranges[i].range_m);
}

TEST(Scenario, FrontWallAnchorsAndPartialHallRuns) {
  ScenarioOptions o;
  o.environment = EnvironmentKind::kHall;
  o.hall.num_anchors = 11;
  o.hall.anchor_walls = HallWalls::kFront;
  o.trajectory.kind = TrajectoryKind::kShort;
  o.trajectory.short_fraction = 0.15;
  const Scenario s = GenerateScenario(o, 2, 0);
  for (const SimAnchor& a : s.anchors) EXPECT_EQ(a.p_world_anchor.y(), 0.0);
  EXPECT_NEAR(s.anchors.front().p_world_anchor.x(), 0.5 * o.hall.length_m / 11, 1e-12);
  double min_x = 1e9, max_x = -1e9;
  for (const Eigen::Vector3d& p : s.p_world_body) {
    min_x = std::min(min_x, p.x());
    max_x = std::max(max_x, p.x());
  }
  EXPECT_LE(max_x - min_x, 0.15 * o.hall.length_m + 1e-9);  // wanders over 15% of the length only
  EXPECT_GT(max_x - min_x, 0.05 * o.hall.length_m);
}

TEST(ScenarioOptions, RejectsImpossibleValues) {
  ScenarioOptions o;
  std::string why;
  EXPECT_TRUE(o.IsValid(&why));
  o.ranging.sigma_range_m = -0.1;
  EXPECT_FALSE(o.IsValid(&why));
  o = {};
  o.tunnel.anchor_height_max_m = 100.0;
  EXPECT_FALSE(o.IsValid(&why));
}

}  // namespace
}  // namespace anchorbench::sim
