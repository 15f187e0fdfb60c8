#include "anchorbench/estimator/front_end.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <gtest/gtest.h>

#include "anchorbench/estimator/ransac_solver.hpp"
#include "anchorbench/estimator/triggers.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::estimator {
namespace {

// Per anchor: the paper's chain, a sample-count chain and a fixed window, all typed.
FrontEnd::ChainFactory ThreeChains(bool defer = false) {
  return [defer](int anchor_id) {
    std::vector<AnchorInitializer> chains;
    chains.push_back(MakePaperInitializer(anchor_id));
    chains.emplace_back(anchor_id, InitializerOptions{}, std::make_unique<ConsistencyFilter>(),
                        std::make_unique<SampleCountTrigger>(150), std::make_shared<AnchorSolver>());
    chains.emplace_back(anchor_id, InitializerOptions{}, std::make_unique<ConsistencyFilter>(),
                        std::make_unique<FixedWindowTrigger>(), std::make_shared<AnchorSolver>());
    for (AnchorInitializer& chain : chains) chain.SetDeferSolves(defer);
    return chains;
  };
}

// A single chain that keeps everything it is given (no filter, no trigger).
FrontEnd::ChainFactory KeepEverything() {
  return [](int anchor_id) {
    std::vector<AnchorInitializer> chains;
    chains.emplace_back(anchor_id, InitializerOptions{}, std::make_unique<NullFilter>(),
                        std::make_unique<FixedWindowTrigger>(), std::make_shared<AnchorSolver>());
    return chains;
  };
}

using EventKey = std::tuple<int, std::size_t, double, int, double, double, double, double>;
std::vector<EventKey> SortedKeys(const std::vector<FrontEndEvent>& events) {
  std::vector<EventKey> keys;
  for (const FrontEndEvent& e : events) {
    const Eigen::Vector3d& p = e.init.solve.p_world_anchor;
    keys.emplace_back(e.anchor_id, e.chain, e.init.t_s, e.init.n_used, e.init.pdop_closest_point, p.x(), p.y(), p.z());
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

// Eight anchors around a hall, a tag on a loop through it at 20 Hz for 120 s, 5% outliers.
std::vector<RangeSample> HallRanges() {
  auto rng = testing::TestStream(3);
  std::vector<Eigen::Vector3d> p_world_anchor;
  for (int a = 0; a < 8; ++a) {
    const double angle = 0.785 * a;
    p_world_anchor.emplace_back(15.0 * std::cos(angle), 10.0 * std::sin(angle), 2.0 + 0.5 * (a % 3));
  }
  std::vector<RangeSample> samples;
  for (int k = 0; k < 2400; ++k) {
    const double t_s = 0.05 * k;
    const Eigen::Vector3d p(10.0 * std::sin(0.05 * t_s), 6.0 * std::sin(0.1 * t_s), 1.0 + 0.3 * std::sin(0.2 * t_s));
    const int anchor = k % 8;
    double range_m = (p - p_world_anchor[anchor]).norm() + 0.1 + 0.05 * rng.Normal();
    if (rng.Bernoulli(0.05)) range_m += rng.Uniform(0.5, 5.0);
    samples.push_back({t_s, 0, anchor + 1, range_m, p});
  }
  return samples;
}

TEST(FrontEnd, DeferredSolvesGiveTheInlineEventsForEveryAnchorAndChain) {
  const std::vector<RangeSample> samples = HallRanges();
  FrontEnd inline_solves(ThreeChains());
  FrontEndOptions defer;
  defer.defer_solves = true;
  FrontEnd deferred(ThreeChains(), defer);
  std::size_t fed = 0;
  for (const RangeSample& sample : samples) {
    inline_solves.AddSample(sample);
    deferred.AddSample(sample);
    if (++fed % 97 == 0) deferred.RunPendingSolves();  // as a navigation stack's idle loop would
  }
  const double t_end_s = samples.back().t_s;
  inline_solves.Finish(t_end_s);
  deferred.Finish(t_end_s);
  const auto expected = SortedKeys(inline_solves.TakeEvents());
  EXPECT_GE(expected.size(), 8u);  // at least every anchor's fixed window
  EXPECT_EQ(SortedKeys(deferred.TakeEvents()), expected);
  EXPECT_FALSE(deferred.HasPendingSolves());
}

TEST(FrontEnd, InterpolatesPosesAtRangeTimesAndNeverExtrapolates) {
  FrontEnd front_end(KeepEverything());
  std::vector<RangeSample> seen;
  front_end.SetSampleObserver([&](const RangeSample& s, const FeedResult&) { seen.push_back(s); });
  int dropped = 0;
  front_end.SetDropObserver([&](const DroppedRange& d) {
    EXPECT_EQ(d.reason, DroppedRange::Reason::kOutsidePoses);
    ++dropped;
  });
  // Poses at 1 Hz from t = 1 s to 11 s; ranges at 10 Hz from t = 0 to 12.9 s, fed in time order.
  auto pose_at = [](double t) { return Eigen::Vector3d(t, 0.5 * t * t, 1.0); };
  int pose = 1;
  for (int k = 0; k < 130; ++k) {
    const double t = 0.1 * k;
    while (pose <= 11 && pose <= t) {
      front_end.AddPose(pose, 0, pose_at(pose));
      ++pose;
    }
    front_end.AddRange(t, 0, 4, 10.0);
  }
  front_end.Finish(13.0);
  EXPECT_EQ(static_cast<int>(seen.size()), 101);  // t = 1.0 ... 11.0
  EXPECT_EQ(dropped, 29);                         // 10 before the first pose, 19 after the last
  EXPECT_EQ(front_end.counters().ranges_outside_poses, 29);
  for (const RangeSample& s : seen) {
    const double t0 = std::floor(s.t_s + 1e-9), t1 = std::min(t0 + 1.0, 11.0);
    const double f = t1 > t0 ? (s.t_s - t0) / (t1 - t0) : 0.0;
    EXPECT_TRUE(s.p_world_tag.isApprox(pose_at(t0) + f * (pose_at(t1) - pose_at(t0)), 1e-12)) << s.t_s;
  }
}

TEST(FrontEnd, RangesWaitForTheirTagsPoseButNotForever) {
  FrontEndOptions options;
  options.max_wait_s = 2.0;
  FrontEnd front_end(KeepEverything(), options);
  long samples = 0;
  front_end.SetSampleObserver([&](const RangeSample&, const FeedResult&) { ++samples; });
  front_end.AddPose(0.0, 0, Eigen::Vector3d::Zero());
  front_end.AddRange(0.5, 0, 1, 3.0);  // its tag's next pose is not there yet
  EXPECT_EQ(samples, 0);
  front_end.AddPose(1.0, 0, Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(samples, 1);  // handed over as soon as the pose after it arrived
  front_end.AddRange(1.5, 7, 1, 3.0);  // tag 7 never reports a pose
  front_end.AddRange(1.6, 0, 1, 3.0);  // waits behind it, in arrival order
  front_end.AddPose(2.0, 0, Eigen::Vector3d(2, 0, 0));
  EXPECT_EQ(samples, 1);
  front_end.AddPose(3.0, 0, Eigen::Vector3d(3, 0, 0));
  front_end.AddPose(4.0, 0, Eigen::Vector3d(4, 0, 0));  // 2.5 s after tag 7's range: it is given up
  EXPECT_EQ(front_end.counters().ranges_without_pose, 1);
  EXPECT_EQ(samples, 2);
}

TEST(PoseBuffer, InterpolatesLinearlyPerTagAndNeverExtrapolates) {
  PoseBuffer poses;
  poses.Add(0, 0.0, Eigen::Vector3d(0, 0, 0));
  poses.Add(0, 1.0, Eigen::Vector3d(2, 4, 6));
  poses.Add(1, 0.5, Eigen::Vector3d(10, 0, 0));
  poses.Add(1, 1.5, Eigen::Vector3d(10, 10, 0));
  Eigen::Vector3d p;
  ASSERT_EQ(poses.At(0, 0.25, &p), PoseBuffer::Lookup::kFound);
  EXPECT_TRUE(p.isApprox(Eigen::Vector3d(0.5, 1.0, 1.5)));  // 1/4 of the way
  ASSERT_EQ(poses.At(1, 1.0, &p), PoseBuffer::Lookup::kFound);
  EXPECT_TRUE(p.isApprox(Eigen::Vector3d(10, 5, 0)));  // tag 1 on its own track
  ASSERT_EQ(poses.At(0, 1.0, &p), PoseBuffer::Lookup::kFound);
  EXPECT_EQ(p, Eigen::Vector3d(2, 4, 6));  // the end point itself
  EXPECT_EQ(poses.At(0, 1.01, &p), PoseBuffer::Lookup::kNotYet);  // a later pose may still come
  EXPECT_EQ(poses.At(1, 0.4, &p), PoseBuffer::Lookup::kOutside);
  EXPECT_EQ(poses.At(7, 0.5, &p), PoseBuffer::Lookup::kNotYet);  // a tag without poses (yet)
}

TEST(FrontEnd, PoseHistoryIsBounded) {
  PoseBufferOptions options;
  options.history_s = 1.0;
  PoseBuffer poses(options);
  for (int k = 0; k <= 10000; ++k) poses.Add(0, 0.01 * k, Eigen::Vector3d(k, 0, 0));
  Eigen::Vector3d p;
  EXPECT_EQ(poses.At(0, 50.0, &p), PoseBuffer::Lookup::kOutside);  // long forgotten
  EXPECT_EQ(poses.At(0, 99.5, &p), PoseBuffer::Lookup::kFound);
  EXPECT_NEAR(p.x(), 9950.0, 1e-6);
  EXPECT_EQ(poses.At(0, 100.5, &p), PoseBuffer::Lookup::kNotYet);
  EXPECT_FALSE(poses.Add(0, 100.0, Eigen::Vector3d::Zero()));  // time must increase
}

}  // namespace
}  // namespace anchorbench::estimator
