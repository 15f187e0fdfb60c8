// The navigation filter's sanity checks (issue 27): with no anchors its covariance describes the
// configured drift; with perfect anchors it is consistent (NEES); with uncertain anchors it stays
// consistent only because it carries their uncertainty as consider states.
#include "anchorbench/nav/navigation_filter.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace anchorbench::nav {
namespace {

constexpr double kNoGate = std::numeric_limits<double>::infinity();
constexpr double kSigmaRange = 0.1;
constexpr int kRuns = 100;  // NEES mean of 3 dof over 100 runs: standard deviation 0.25

struct Trajectory {
  std::vector<double> t_s;
  std::vector<Eigen::Vector3d> p_world_tag;
};

// A loop of a ground robot at 10 Hz for 120 s.
Trajectory Loop() {
  Trajectory trajectory;
  for (int k = 0; k <= 1200; ++k) {
    const double t = 0.1 * k;
    trajectory.t_s.push_back(t);
    trajectory.p_world_tag.emplace_back(10.0 * std::cos(0.05 * t), 6.0 * std::sin(0.1 * t), 0.3 + 0.2 * std::sin(0.3 * t));
  }
  return trajectory;
}

const std::vector<Eigen::Vector3d> kFilterAnchors = {{15, 10, 3}, {-15, 10, 1}, {-15, -10, 3}, {15, -10, 1}};

struct Anchors {
  std::vector<Eigen::Vector3d> p_world_anchor;  // what the filter is told
  std::vector<double> bias_m;
  Eigen::Matrix4d covariance = Eigen::Matrix4d::Zero();  // told to the filter
};

// The position NEES at the end of one run: odometry drift, ranges every step to each anchor (none
// when `anchors` is null).
double FinalNees(int run, const Anchors* anchors, const OdometryDrift& drift, double* error_m = nullptr) {
  const Trajectory truth = Loop();
  sim::RandomStream rng(77, static_cast<std::uint64_t>(run), 12);
  const std::vector<OdometryStep> steps = SimulateOdometry(truth.t_s, truth.p_world_tag, drift, rng);
  constexpr double kSigmaStart = 0.05;
  Eigen::Vector3d start = truth.p_world_tag[0];
  for (int i = 0; i < 3; ++i) start[i] += kSigmaStart * rng.Normal();
  NavigationFilter filter(start, kSigmaStart, drift);
  if (anchors) {
    for (std::size_t a = 0; a < kFilterAnchors.size(); ++a) {
      filter.AddAnchor(static_cast<int>(a), anchors->p_world_anchor[a], anchors->bias_m[a], anchors->covariance);
    }
  }
  for (std::size_t k = 0; k < steps.size(); ++k) {
    filter.Predict(steps[k]);
    if (!anchors) continue;
    if (k % 5 != 4) continue;  // ranges at 2 Hz
    for (std::size_t a = 0; a < kFilterAnchors.size(); ++a) {
      const double d = (truth.p_world_tag[k + 1] - kFilterAnchors[a]).norm() + 0.2 + kSigmaRange * rng.Normal();
      filter.UpdateRange(static_cast<int>(a), d, kSigmaRange, kNoGate);
    }
  }
  const Eigen::Vector3d error = filter.position() - truth.p_world_tag.back();
  if (error_m) *error_m = error.norm();
  return error.dot(filter.position_covariance().ldlt().solve(error));
}

double MeanNees(const std::function<double(int)>& nees) {
  double sum = 0.0;
  for (int run = 0; run < kRuns; ++run) sum += nees(run);
  return sum / kRuns;
}

TEST(NavigationFilter, WithoutAnchorsItsCovarianceIsTheConfiguredDrift) {
  const OdometryDrift drift{0.004, 0.002, 0.02};  // a wheel odometry's order of magnitude
  double error_sum = 0.0;
  const double nees = MeanNees([&](int run) {
    double error = 0.0;
    const double value = FinalNees(run, nullptr, drift, &error);
    error_sum += error;
    return value;
  });
  EXPECT_NEAR(nees, 3.0, 0.75);
  EXPECT_GT(error_sum / kRuns, 0.2);  // 120 s of drift: tens of centimetres, not millimetres
  // Four times the drift's variance: the same NEES (the covariance follows the configured walks).
  const OdometryDrift doubled{0.008, 0.004, 0.04};
  EXPECT_NEAR(MeanNees([&](int run) { return FinalNees(run, nullptr, doubled); }), 3.0, 0.75);
}

TEST(NavigationFilter, WithPerfectAnchorsItIsConsistentAndAccurate) {
  const OdometryDrift drift{0.004, 0.002, 0.02};
  Anchors perfect{kFilterAnchors, std::vector<double>(kFilterAnchors.size(), 0.2), Eigen::Matrix4d::Zero()};
  double error_sum = 0.0;
  const double nees = MeanNees([&](int run) {
    double error = 0.0;
    const double value = FinalNees(run, &perfect, drift, &error);
    error_sum += error;
    return value;
  });
  EXPECT_NEAR(nees, 3.0, 0.75);
  double drift_sum = 0.0;
  for (int run = 0; run < kRuns; ++run) {
    double error = 0.0;
    FinalNees(run, nullptr, drift, &error);
    drift_sum += error;
  }
  EXPECT_LT(error_sum, 0.5 * drift_sum);  // ranges to four anchors at least halve 120 s of drift
}

// Anchors placed wrong by their reported covariance (0.1-0.2 m: a good initialization's):
// consistent with the consider states, and overconfident when the filter is told the anchors are
// exact. At 0.3-0.5 m the EKF's linearization shows: the mean NEES reached 4.5 (measured while
// writing this test), so the consistency claim is for initializations within a few decimetres.
TEST(NavigationFilter, AnAnchorsUncertaintyIsCarriedNotAveragedAway) {
  const OdometryDrift drift{0.004, 0.002, 0.02};
  const Eigen::Vector4d sigma(0.1, 0.1, 0.2, 0.02);
  auto nees_with = [&](bool told) {
    return MeanNees([&](int run) {
      sim::RandomStream rng(91, static_cast<std::uint64_t>(run), 13);
      Anchors wrong;
      for (const Eigen::Vector3d& p : kFilterAnchors) {
        wrong.p_world_anchor.push_back(p + Eigen::Vector3d(sigma[0] * rng.Normal(), sigma[1] * rng.Normal(),
                                                           sigma[2] * rng.Normal()));
        wrong.bias_m.push_back(0.2 + sigma[3] * rng.Normal());
      }
      if (told) wrong.covariance = sigma.cwiseProduct(sigma).asDiagonal();
      return FinalNees(run, &wrong, drift);
    });
  };
  const double told = nees_with(true), untold = nees_with(false);
  EXPECT_NEAR(told, 3.0, 0.75);
  EXPECT_GT(untold, 3.0 * told) << "told " << told;
}

TEST(NavigationFilter, UnknownAnchorsAndGatedRangesLeaveTheStateAlone) {
  NavigationFilter filter(Eigen::Vector3d::Zero(), 0.1, {});
  EXPECT_FALSE(filter.UpdateRange(4, 10.0, kSigmaRange, kNoGate));
  filter.AddAnchor(4, Eigen::Vector3d(10, 0, 0), 0.0, Eigen::Matrix4d::Zero());
  EXPECT_FALSE(filter.UpdateRange(4, 25.0, kSigmaRange, 9.0));  // 15 m off: beyond a 3-sigma gate
  EXPECT_EQ(filter.position(), Eigen::Vector3d::Zero());
  EXPECT_TRUE(filter.UpdateRange(4, 10.05, kSigmaRange, 9.0));
  EXPECT_NE(filter.position(), Eigen::Vector3d::Zero());
}

// An anchor whose height is mirror-ambiguous, placed at its mirror below the tag's plane: as it
// is, its range pulls the tag's height the wrong way; for x-y only, the height is left alone and
// the horizontal position is still corrected.
TEST(NavigationFilter, AHorizontalOnlyAnchorCorrectsXyAndLeavesTheHeight) {
  const Eigen::Vector3d p_true(0.0, 0.0, 0.0), p_mirror_anchor(6.0, 0.0, -3.0);  // the truth: (6, 0, 3)
  const double range = (p_true - Eigen::Vector3d(6.0, 0.0, 3.0)).norm();
  auto after_ranges = [&](bool horizontal_only) {
    NavigationFilter filter(Eigen::Vector3d(0.5, 0.0, 0.0), 0.5, {});
    filter.AddAnchor(1, p_mirror_anchor, 0.0, Eigen::Matrix4d::Zero(), horizontal_only);
    for (int i = 0; i < 5; ++i) EXPECT_TRUE(filter.UpdateRange(1, range, kSigmaRange, kNoGate));
    return filter.position();
  };
  const Eigen::Vector3d as_is = after_ranges(false), xy_only = after_ranges(true);
  EXPECT_EQ(xy_only.z(), 0.0);
  EXPECT_LT(std::abs(xy_only.x()), 0.05);  // started 0.5 m off along the anchor's horizontal direction
  EXPECT_GT(std::abs(as_is.z()), 0.1);     // the mirror's vertical pull
}

}  // namespace
}  // namespace anchorbench::nav
