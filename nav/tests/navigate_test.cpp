// One run of the navigation filter: anchors from the start (the floor), late, or never (the drift).
#include "anchorbench/nav/navigate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace anchorbench::nav {
namespace {

struct RobotRun {
  std::vector<double> t_s;
  std::vector<Eigen::Vector3d> p_world_tag;
  std::vector<OdometryStep> odometry;
  std::vector<RangeAt> ranges;
};

const std::vector<Eigen::Vector3d> kAnchors = {{15, 10, 3}, {-15, 10, 1}, {-15, -10, 3}, {15, -10, 1}};

// 120 s of a ground robot's loop at 10 Hz, ranges at 2 Hz to every anchor (bias 0.2 m), a share
// of them outliers 1-5 m long.
RobotRun MakeRun(int seed, double outlier_share = 0.0) {
  RobotRun run;
  for (int k = 0; k <= 1200; ++k) {
    const double t = 0.1 * k;
    run.t_s.push_back(t);
    run.p_world_tag.emplace_back(10.0 * std::cos(0.05 * t), 6.0 * std::sin(0.1 * t), 0.3 + 0.2 * std::sin(0.3 * t));
  }
  sim::RandomStream rng(5, static_cast<std::uint64_t>(seed), 12);
  run.odometry = SimulateOdometry(run.t_s, run.p_world_tag, {0.004, 0.002, 0.02}, rng);
  for (std::size_t k = 0; k < run.t_s.size(); k += 5) {
    for (std::size_t a = 0; a < kAnchors.size(); ++a) {
      double d = (run.p_world_tag[k] - kAnchors[a]).norm() + 0.2 + 0.1 * rng.Normal();
      if (rng.Uniform() < outlier_share) d += rng.Uniform(1.0, 5.0);
      run.ranges.push_back({k, static_cast<int>(a), d});
    }
  }
  return run;
}

std::vector<UsableAnchor> TrueAnchors(double t_init_s) {
  std::vector<UsableAnchor> anchors;
  for (std::size_t a = 0; a < kAnchors.size(); ++a) {
    anchors.push_back({static_cast<int>(a), t_init_s + a, kAnchors[a], 0.2, Eigen::Matrix4d::Zero()});
  }
  return anchors;
}

NavigationOutcome NavigateRun(const RobotRun& run, std::vector<UsableAnchor> anchors) {
  return Navigate(run.t_s, run.p_world_tag, run.odometry, run.p_world_tag.front(), run.ranges, std::move(anchors), {});
}

TEST(Navigate, AnchorsFromTheStartBeatLateOnesWhichBeatNone) {
  double floor = 0.0, late = 0.0, drift = 0.0, late_final = 0.0, drift_final = 0.0;
  for (int seed = 0; seed < 20; ++seed) {
    const RobotRun run = MakeRun(seed);
    const NavigationOutcome at_start = NavigateRun(run, TrueAnchors(0.0));
    const NavigationOutcome at_60 = NavigateRun(run, TrueAnchors(60.0));
    const NavigationOutcome never = NavigateRun(run, {});
    floor += at_start.rmse_m;
    late += at_60.rmse_m;
    drift += never.rmse_m;
    late_final += at_60.final_error_m;
    drift_final += never.final_error_m;
    EXPECT_EQ(never.fix_share, 0.0);
    EXPECT_FALSE(never.t_first_anchor_s.has_value());
    EXPECT_EQ(at_60.t_first_anchor_s, 60.0);
    EXPECT_EQ(at_60.t_kth_anchor_s, 62.0);  // the third anchor, a second apart
    EXPECT_NEAR(at_60.fix_share, 0.48, 0.01);
    EXPECT_GT(at_start.fix_share, 0.97);
  }
  EXPECT_LT(floor, late);
  EXPECT_LT(late, drift);
  EXPECT_LT(late_final, 0.5 * drift_final);  // once anchors help, the drift is taken back
}

TEST(Navigate, OutliersAreGatedAndTheRunStaysNearTheFloor) {
  double clean = 0.0, dirty = 0.0;
  long gated = 0;
  for (int seed = 0; seed < 10; ++seed) {
    clean += NavigateRun(MakeRun(seed), TrueAnchors(0.0)).rmse_m;
    const NavigationOutcome outcome = NavigateRun(MakeRun(seed, 0.1), TrueAnchors(0.0));
    dirty += outcome.rmse_m;
    gated += outcome.ranges_gated;
  }
  EXPECT_GT(gated, 0);
  EXPECT_LT(dirty, 2.0 * clean);
}

TEST(Navigate, RefusesATrajectoryWithoutItsOdometry) {
  const RobotRun run = MakeRun(0);
  EXPECT_THROW(Navigate(run.t_s, run.p_world_tag, std::span(run.odometry).first(10), run.p_world_tag.front(), run.ranges,
                        {}, {}),
               std::invalid_argument);
}

TEST(Navigate, TheErrorOverTimeIsKeptPerBinAndAGapIsNoNumber) {
  const RobotRun run = MakeRun(3);
  NavigationOptions options;
  options.error_bin_s = 10.0;
  const NavigationOutcome never =
      Navigate(run.t_s, run.p_world_tag, run.odometry, run.p_world_tag.front(), run.ranges, {}, options);
  ASSERT_EQ(never.error_by_bin_m.size(), 13u);  // 120 s: 12 bins of 10 s and the last epoch's
  EXPECT_LT(never.error_by_bin_m.front(), never.error_by_bin_m[11]);  // the drift grows
  EXPECT_NEAR(never.error_by_bin_m.back(), never.final_error_m, 1e-12);  // the last bin: one epoch

  RobotRun gap = run;  // no epoch between 40 and 60 s
  std::vector<double> t_s;
  std::vector<Eigen::Vector3d> p;
  for (std::size_t k = 0; k < gap.t_s.size(); ++k) {
    if (gap.t_s[k] < 40.0 || gap.t_s[k] >= 60.0) {
      t_s.push_back(gap.t_s[k]);
      p.push_back(gap.p_world_tag[k]);
    }
  }
  sim::RandomStream rng(5, 0, 12);
  const std::vector<OdometryStep> odometry = SimulateOdometry(t_s, p, {0.004, 0.002, 0.02}, rng);
  const NavigationOutcome gapped = Navigate(t_s, p, odometry, p.front(), {}, {}, options);
  ASSERT_EQ(gapped.error_by_bin_m.size(), 13u);
  EXPECT_TRUE(std::isnan(gapped.error_by_bin_m[4]));
  EXPECT_TRUE(std::isnan(gapped.error_by_bin_m[5]));
  EXPECT_TRUE(std::isfinite(gapped.error_by_bin_m[6]));
}

}  // namespace
}  // namespace anchorbench::nav
