#include "anchorbench/estimator/anchor_initializer.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "anchorbench/estimator/components.hpp"
#include "anchorbench/estimator/pdop.hpp"
#include "test_data.hpp"

namespace anchorbench::estimator {
namespace {

using testing::Builtins;
using testing::PassBy;

// Named, not `{}`: GCC 12 warns falsely (-Wmaybe-uninitialized) on brace temporaries of it.
const InitializerOptions kDefaults;

TEST(AnchorInitializer, GatedFiresOnceWhenPdopDropsBelowThreshold) {
  const Eigen::Vector3d p_anchor(0, 4, 3);
  InitializerOptions options;
  options.trigger.pdop_threshold = 1.0;
  AnchorInitializer initializer(7, options);
  std::optional<InitEvent> event;
  double pdop_before = 0.0;
  for (const RangeSample& s : PassBy(p_anchor, 0.05, 1)) {
    const FeedResult fed = initializer.Feed(s);
    if (fed.event) {
      ASSERT_FALSE(event.has_value()) << "fired twice";
      event = fed.event;
      EXPECT_LT(fed.pdop, 1.0);
      EXPECT_GE(pdop_before, 1.0);  // the trigger fires on the first sample below the threshold
    }
    if (!event) pdop_before = fed.pdop;
  }
  ASSERT_TRUE(event.has_value());
  EXPECT_EQ(event->anchor_id, 7);
  EXPECT_EQ(event->n_used, static_cast<int>(initializer.range_m().size()));
  // Error budget: sigma * PDOP = 0.05 m; allow 5x for the bias column and a single realization.
  EXPECT_LT((event->solve.p_world_anchor - p_anchor).norm(), 0.25);
  EXPECT_FALSE(initializer.Finish(event->t_s).has_value());
}

TEST(AnchorInitializer, FixedWindowSolvesOnAllDataAtFinish) {
  const Eigen::Vector3d p_anchor(0, 4, 3);
  AnchorInitializer initializer = MakeInitializer(Builtins(), 7, kDefaults, "fixed_window", 0);
  const auto samples = PassBy(p_anchor, 0.05, 2);
  for (const RangeSample& s : samples) EXPECT_FALSE(initializer.Feed(s).event.has_value());
  const auto event = initializer.Finish(samples.back().t_s);
  ASSERT_TRUE(event.has_value());
  EXPECT_EQ(event->n_used, static_cast<int>(initializer.range_m().size()));
  EXPECT_GT(event->n_used, static_cast<int>(0.98 * samples.size()));  // tau = 2.8 sigma of a difference
  EXPECT_LT((event->solve.p_world_anchor - p_anchor).norm(), 0.1);
}

TEST(AnchorInitializer, NeverFiresOnAStraightLine) {
  InitializerOptions options;
  AnchorInitializer initializer(1, options);
  for (int k = 0; k < 2000; ++k) {
    const Eigen::Vector3d p(0.05 * k, 0.0, 1.0);
    const FeedResult fed = initializer.Feed({0.1 * k, 0, 1, (p - Eigen::Vector3d(50, 3, 3)).norm(), p});
    EXPECT_FALSE(fed.event.has_value());
    EXPECT_FALSE(std::isnan(fed.pdop));
  }
}

TEST(AnchorInitializer, RejectsNonPositiveRanges) {
  AnchorInitializer initializer(1, kDefaults);
  EXPECT_FALSE(initializer.Feed({0.0, 0, 1, 0.0, Eigen::Vector3d::Zero()}).accepted);
  EXPECT_FALSE(initializer.Feed({0.1, 0, 1, -1.0, Eigen::Vector3d::Zero()}).accepted);
  EXPECT_TRUE(initializer.Feed({0.2, 0, 1, 3.0, Eigen::Vector3d::Zero()}).accepted);
}

TEST(InitializerOptions, ValidationNamesTheProblem) {
  InitializerOptions options;
  std::string why;
  EXPECT_TRUE(options.IsValid(&why));
  options.filter.consistency.tau_m = -1.0;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_NE(why.find("tau"), std::string::npos);
}

}  // namespace
}  // namespace anchorbench::estimator
