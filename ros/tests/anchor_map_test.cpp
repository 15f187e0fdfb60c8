// The node's logic without ROS: the published trigger's anchors from poses and ranges, what the
// others wait for, reset, the saved files, the rviz ellipsoid and the anchor id of a frame.
#include "anchor_map.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>


namespace anchorbench::ros_node {
namespace {

const Eigen::Vector3d kAnchors[] = {{3.0, 4.0, 2.5}, {-4.0, 1.0, 3.0}, {40.0, 40.0, 2.0}};  // the last out of reach

// A tag that wanders around the first two anchors, up and down, at 10 Hz: poses and ranges (the far
// anchor ranged too, from a distance no geometry resolves in a minute).
void Feed(AnchorMap& map, double seconds) {
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.05);
  for (int k = 0; 0.1 * k <= seconds; ++k) {
    const double t = 0.1 * k;
    const Eigen::Vector3d p(5.0 * std::cos(0.21 * t), 4.0 * std::sin(0.17 * t), 1.0 + 1.2 * std::sin(0.11 * t));
    map.AddPose(t, 0, p);
    for (int a = 0; a < 3; ++a) map.AddRange(t, 0, a, (p - kAnchors[a]).norm() + 0.1 + noise(rng));
  }
}

std::vector<AnchorState> RunSolves(AnchorMap& map) {
  std::vector<AnchorState> all;
  for (;;) {
    std::vector<AnchorState> fresh = map.Step(1000, AnchorMap::Clock::time_point::max());
    if (fresh.empty() && map.pending_solves() == 0) return all;
    all.insert(all.end(), fresh.begin(), fresh.end());
  }
}

TEST(AnchorMap, PublishesTheCertifiedAnchorsAndSaysWhatTheOthersWaitFor) {
  AnchorMap map("", {}, "");
  EXPECT_EQ(map.trigger(), "certified");  // the defaults list it
  Feed(map, 120.0);
  const std::vector<AnchorState> fresh = RunSolves(map);
  ASSERT_EQ(fresh.size(), 2u);
  for (const AnchorState& anchor : fresh) {
    EXPECT_LT((anchor.p_world_anchor - kAnchors[anchor.anchor_id]).norm(), 0.75);
  }
  const std::vector<AnchorState> states = map.States();
  ASSERT_EQ(states.size(), 3u);
  EXPECT_TRUE(states[0].initialized && states[1].initialized);
  EXPECT_FALSE(states[2].initialized);
  EXPECT_FALSE(states[2].waiting_for.empty());
  EXPECT_GT(states[2].samples, 0);

  const std::string csv = AnchorsCsv(states);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "anchor_id,x,y,z,bias,t_init,n_used,var_x,var_y,var_z");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);  // the header and the two initialized
  EXPECT_NE(AnchorsYaml(states, "map").find("frame_id: \"map\""), std::string::npos);

  EXPECT_TRUE(map.Reset(0));
  EXPECT_FALSE(map.Reset(99));
  EXPECT_FALSE(map.States()[0].initialized);
  map.Reset();
  for (const AnchorState& state : map.States()) EXPECT_FALSE(state.initialized);
}

// What anchor 0 waits for after `seconds` of a tag along `path` at 10 Hz (noise 0.05 m, seed
// `seed`), where only it is ranged and the certificate waits on its mirror.
template <typename Path>
std::string MirrorWait(Path path, double seconds, unsigned seed) {
  AnchorMap map("", {}, "");
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.05);
  for (int k = 0; 0.1 * k <= seconds; ++k) {
    const double t = 0.1 * k;
    const Eigen::Vector3d p = path(t);
    map.AddPose(t, 0, p);
    map.AddRange(t, 0, 0, (p - kAnchors[0]).norm() + 0.1 + noise(rng));
  }
  RunSolves(map);
  const std::vector<AnchorState> states = map.States();
  if (states.size() != 1u || states[0].initialized) return "initialized";
  EXPECT_EQ(states[0].waiting_for.rfind("mirror", 0), 0u) << states[0].waiting_for;
  return states[0].waiting_for;
}

// A ground robot's loop (the tag within 2 mm of one height): the certificate waits on each anchor's
// mirror, and the diagnostics say whether more of the same path would settle it.
TEST(AnchorMap, AMirrorsWaitSaysWhetherMoreOfTheSamePathWouldSettleIt) {
  const std::string waiting = MirrorWait(
      [](double t) {
        return Eigen::Vector3d(5.0 * std::cos(0.21 * t), 4.0 * std::sin(0.17 * t), 1.0 + 0.002 * std::sin(0.9 * t));
      },
      120.0, 5);
  EXPECT_NE(waiting.find("settle"), std::string::npos) << waiting;
}

// A ground robot 7-13 m from an anchor 0.5 m above its tags, rising and falling 0.1 m: the mirror
// fits worse, but by less than the model error could explain, and the diagnostics say so.
TEST(AnchorMap, AMirrorsWaitSaysWhatTheModelErrorCouldExplain) {
  const std::string waiting = MirrorWait(
      [](double t) -> Eigen::Vector3d {
        return kAnchors[0] + Eigen::Vector3d(-4.0 + 6.0 * std::cos(0.05 * t), 10.0 + 3.0 * std::sin(0.031 * t),
                                             -0.5 + 0.1 * std::sin(0.4 * t));
      },
      600.0, 3);
  EXPECT_NE(waiting.find("the model error could explain"), std::string::npos) << waiting;
}

// Guidance for the anchors it waits for only: the far one, its best candidates ranked, and the test
// that holds it.
TEST(AnchorMap, GuidesOnlyTheAnchorsItWaitsFor) {
  AnchorMap map("", {}, "");
  Feed(map, 120.0);
  RunSolves(map);
  const std::vector<AnchorGuide> guides = map.Guide(2.0, 2, 3, 10.0);
  ASSERT_EQ(guides.size(), 1u);
  EXPECT_EQ(guides[0].anchor_id, 2);
  EXPECT_EQ(map.States()[2].waiting_for.rfind(guides[0].blocked_by, 0), 0u);  // the same test first
  ASSERT_EQ(guides[0].p_world_candidate.size(), 3u);
  ASSERT_EQ(guides[0].samples_to_certify.size(), 3u);
  EXPECT_GT(guides[0].region_m, guides[0].accuracy_m);
  double fewest = INFINITY;
  for (const double samples : guides[0].samples_to_certify) fewest = std::min(fewest, samples);
  EXPECT_DOUBLE_EQ(guides[0].seconds_to_certify, fewest / 10.0);
}

// The waypoints: each anchor's best candidate that closes its region, the soonest first.
TEST(AnchorMap, WaypointsAreTheCandidatesThatCertifySoonestFirst) {
  auto guide = [](int anchor_id, double seconds, double x) {
    AnchorGuide g;
    g.anchor_id = anchor_id;
    g.seconds_to_certify = seconds;
    g.p_world_candidate = {Eigen::Vector3d(x, 0.0, 0.0), Eigen::Vector3d(-x, 0.0, 0.0)};
    return g;
  };
  const std::vector<Eigen::Vector3d> waypoints =
      WaypointsOf({guide(1, 4.0, 1.0), guide(2, INFINITY, 2.0), guide(3, 0.5, 3.0), guide(4, 4.0, 4.0)});
  ASSERT_EQ(waypoints.size(), 3u);  // anchor 2: no candidate closes it
  EXPECT_EQ(waypoints[0].x(), 3.0);
  EXPECT_EQ(waypoints[1].x(), 1.0);  // a tie: the lower anchor first
  EXPECT_EQ(waypoints[2].x(), 4.0);
  EXPECT_TRUE(WaypointsOf({}).empty());
}

TEST(AnchorMap, RefusesAnOfflineOrUnknownTrigger) {
  EXPECT_THROW(AnchorMap("", {}, "fixed_window"), BadSetting);
  EXPECT_THROW(AnchorMap("", {}, "no_such_trigger"), BadSetting);
  EXPECT_THROW(AnchorMap("", {}, "pdop_true"), BadSetting);  // needs the truth
  EXPECT_THROW(AnchorMap("", {"estimator.bogus=1"}, ""), BadSetting);
  EXPECT_EQ(AnchorMap("", {}, "pdop_closest_point").trigger(), "pdop_closest_point");
}

TEST(Ellipsoid, HasTheConfidenceRegionsAxes) {
  const Eigen::Matrix3d covariance = Eigen::Vector3d(0.04, 0.01, 0.0025).asDiagonal();
  const Ellipsoid e = EllipsoidOf(covariance);
  const double k = std::sqrt(11.3449);  // chi2_3(0.99)
  Eigen::Vector3d sorted = e.diameters_m;
  std::sort(sorted.data(), sorted.data() + 3);
  EXPECT_NEAR(sorted(0), 2 * k * 0.05, 1e-3);
  EXPECT_NEAR(sorted(2), 2 * k * 0.2, 1e-3);
  EXPECT_NEAR(e.orientation.norm(), 1.0, 1e-12);
}

TEST(AnchorIdFromFrame, ReadsTheTrailingDigits) {
  EXPECT_EQ(AnchorIdFromFrame("anchor_12"), 12);
  EXPECT_EQ(AnchorIdFromFrame("7"), 7);
  EXPECT_EQ(AnchorIdFromFrame("uwb/a3"), 3);
  EXPECT_FALSE(AnchorIdFromFrame("anchor"));
  EXPECT_FALSE(AnchorIdFromFrame(""));
  EXPECT_FALSE(AnchorIdFromFrame("a12345678901"));
}

}  // namespace
}  // namespace anchorbench::ros_node
