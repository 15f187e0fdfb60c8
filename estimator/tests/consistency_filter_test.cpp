#include "anchorbench/estimator/consistency_filter.hpp"

#include <gtest/gtest.h>

#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::estimator {
namespace {

struct Stream {
  std::vector<Eigen::Vector3d> p;
  std::vector<double> d;
  std::vector<bool> spike;
};

// A tag driving past an anchor at 1 m/s, 10 Hz, sigma 0.05 m, with 5% spikes of 1-10 m of either sign.
Stream MakeStream(std::uint64_t seed, double spike_probability) {
  auto rng = testing::TestStream(seed);
  Stream s;
  const Eigen::Vector3d p_anchor(20, 3, 2);
  for (int k = 0; k < 400; ++k) {
    s.p.emplace_back(0.1 * k, 0.5 * std::sin(0.05 * k), 1.0);
    double d = (s.p.back() - p_anchor).norm() + 0.05 * rng.Normal();
    const bool spike = k > 0 && rng.Uniform() < spike_probability;
    if (spike) d += (rng.Uniform() < 0.5 ? -1 : 1) * rng.Uniform(1.0, 10.0);
    s.d.push_back(d);
    s.spike.push_back(spike);
  }
  return s;
}

TEST(ConsistencyFilter, KeepsCleanData) {
  const Stream s = MakeStream(1, 0.0);
  ConsistencyFilter filter({.tau_m = 0.2, .reseed_after_rejections = 10});
  for (std::size_t k = 0; k < s.d.size(); ++k) EXPECT_TRUE(filter.Accept(0, s.p[k], s.d[k])) << k;
}

TEST(ConsistencyFilter, RejectsInjectedSpikes) {
  const Stream s = MakeStream(2, 0.05);
  ConsistencyFilter filter({.tau_m = 0.2, .reseed_after_rejections = 10});
  int spikes = 0, spikes_rejected = 0, clean = 0, clean_accepted = 0;
  for (std::size_t k = 0; k < s.d.size(); ++k) {
    const bool accepted = filter.Accept(0, s.p[k], s.d[k]);
    if (s.spike[k]) {
      ++spikes;
      spikes_rejected += !accepted;
    } else {
      ++clean;
      clean_accepted += accepted;
    }
  }
  ASSERT_GT(spikes, 10);
  EXPECT_EQ(spikes_rejected, spikes);  // every spike exceeds 1 m >> tau + 0.1 m of motion
  EXPECT_EQ(clean_accepted, clean);    // 0.2 m = 4 sigma of the difference... and no spike became a reference
}

TEST(ConsistencyFilter, ReseedsAfterAnOutlyingFirstSample) {
  const Stream s = MakeStream(3, 0.0);
  ConsistencyFilter filter({.tau_m = 0.2, .reseed_after_rejections = 5});
  EXPECT_TRUE(filter.Accept(0, s.p[0], s.d[0] + 20.0));  // first sample: nothing to compare with
  for (int k = 1; k < 5; ++k) EXPECT_FALSE(filter.Accept(0, s.p[k], s.d[k]));
  EXPECT_TRUE(filter.Accept(0, s.p[5], s.d[5]));  // fifth rejection in a row: re-seed here
  for (int k = 6; k < 50; ++k) EXPECT_TRUE(filter.Accept(0, s.p[k], s.d[k]));
}

TEST(ConsistencyFilter, ChecksEachTagAgainstItsOwnHistory) {
  ConsistencyFilter filter;
  EXPECT_TRUE(filter.Accept(0, Eigen::Vector3d(0, 0, 0), 10.0));
  EXPECT_TRUE(filter.Accept(1, Eigen::Vector3d(0, 0.85, 0), 10.5));  // other tag, first sample
  EXPECT_TRUE(filter.Accept(0, Eigen::Vector3d(0.1, 0, 0), 10.05));
  EXPECT_FALSE(filter.Accept(1, Eigen::Vector3d(0.1, 0.85, 0), 13.0));
}

TEST(NullFilter, AcceptsEverything) {
  NullFilter filter;
  EXPECT_TRUE(filter.Accept(RangeSample{0.0, 0, 1, 1.0, Eigen::Vector3d::Zero()}));
  EXPECT_TRUE(filter.Accept(RangeSample{0.1, 0, 1, 100.0, Eigen::Vector3d::Zero()}));
}

}  // namespace
}  // namespace anchorbench::estimator
