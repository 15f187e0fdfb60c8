// The built-in filters as an initializer uses them: online (consistency, none) and at solve time
// (ransac).
#include <gtest/gtest.h>

#include "anchorbench/registry/components.hpp"
#include "builtins.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace anchorbench::registry {
namespace {

using anchorbench::testing::PassBy;
using estimator::AnchorInitializer;
using estimator::InitEvent;
using estimator::RangeSample;
using testing::Builtins;

const Eigen::Vector3d kFilteredAnchor(0, 4, 3);

// Every 5th range 2-6 m long (NLOS), the rest clean. The first sample is clean: when it is an
// outlier, the check can lock onto the outlier series (see docs/method.md).
std::vector<RangeSample> WithOutliers(std::uint64_t seed) {
  std::vector<RangeSample> samples = PassBy(kFilteredAnchor, 0.05, seed);
  auto rng = anchorbench::testing::TestStream(seed + 100);
  for (std::size_t i = 2; i < samples.size(); i += 5) samples[i].range_m += rng.Uniform(2.0, 6.0);
  return samples;
}

std::optional<InitEvent> FixedWindow(const std::string& filter, const std::vector<RangeSample>& samples) {
  schema::EstimatorConfig options;
  options.filter.kind = filter;
  options.solver = "lm_l2";  // plain least squares: only the filter stands between it and the outliers
  AnchorInitializer initializer = MakeInitializer(Builtins(), 7, options, "fixed_window", 11);
  for (const RangeSample& s : samples) initializer.Feed(s);
  return initializer.Finish(samples.back().t_s);
}

TEST(Filters, NoneKeepsEverythingAndLetsOutliersThrough) {
  const auto samples = WithOutliers(1);
  const auto none = FixedWindow("none", samples);
  const auto consistency = FixedWindow("consistency", samples);
  ASSERT_TRUE(none && consistency);
  EXPECT_EQ(none->n_used, static_cast<int>(samples.size()));
  // 20% of ranges 2-6 m long: the bias soaks up their mean, the rest lands on the position.
  EXPECT_GT((none->solve.p_world_anchor - kFilteredAnchor).norm(), 3.0 * (consistency->solve.p_world_anchor - kFilteredAnchor).norm());
}

TEST(Filters, ConsistencyDropsTheOutliersOnline) {
  const auto samples = WithOutliers(1);
  const auto event = FixedWindow("consistency", samples);
  ASSERT_TRUE(event);
  // 240 outliers; tau = 0.2 m is 2.8 sigma of a clean difference, so a few clean ones go too.
  EXPECT_LE(event->n_used, static_cast<int>(samples.size()) - 240);
  EXPECT_GE(event->n_used, static_cast<int>(samples.size()) - 240 - 30);
  EXPECT_LT((event->solve.p_world_anchor - kFilteredAnchor).norm(), 0.1);
}

TEST(Filters, RansacKeepsEverythingOnlineAndRemovesOutliersAtSolveTime) {
  const auto samples = WithOutliers(1);
  const auto event = FixedWindow("ransac", samples);
  ASSERT_TRUE(event);
  EXPECT_EQ(event->n_used, static_cast<int>(samples.size()));  // n_used counts the buffer handed over
  EXPECT_LT((event->solve.p_world_anchor - kFilteredAnchor).norm(), 0.1);
  // Same seed, same subsets: the result repeats exactly.
  EXPECT_EQ(FixedWindow("ransac", samples)->solve.p_world_anchor, event->solve.p_world_anchor);
}

}  // namespace
}  // namespace anchorbench::registry
