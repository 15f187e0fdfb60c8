// The example part as a config names it: built with its own options, firing once the tag's
// positions span what it asks, and saying how far it still has to go.
#include <cmath>

#include <gtest/gtest.h>

#include "anchorbench/example_parts/example_parts.hpp"

namespace anchorbench::example_parts {
namespace {

// A chain of the travel_span trigger alone, its options as a config set them.
estimator::AnchorInitializer Chain(const registry::Components& components, const schema::PartOptionValues& own) {
  schema::EstimatorConfig config;
  config.triggers = {"travel_span"};
  config.initializer.min_samples = 5;
  if (!own.empty()) config.part_options["travel_span"] = own;
  return registry::MakeInitializer(components, 0, config, "travel_span", 1);
}

// The tag circles the anchor at the origin, 10 m out, 1 m a sample, rising and falling by 1 m.
Eigen::Vector3d PathAt(int i) {
  return {10.0 * std::cos(0.1 * i), 10.0 * std::sin(0.1 * i), 1.0 + 0.5 * std::sin(i / 3.0)};
}

// The diagonal of the box around the path's first n + 1 positions.
double SpanAfter(int n) {
  Eigen::Vector3d low = PathAt(0), high = PathAt(0);
  for (int i = 1; i <= n; ++i) {
    low = low.cwiseMin(PathAt(i));
    high = high.cwiseMax(PathAt(i));
  }
  return (high - low).norm();
}

// The sample at which the chain solves, or -1.
int FiresAt(estimator::AnchorInitializer chain) {
  for (int i = 0; i < 60; ++i) {
    const Eigen::Vector3d p_world_tag = PathAt(i);
    if (chain.Feed({static_cast<double>(i), 0, 0, p_world_tag.norm(), p_world_tag}).event) return i;
  }
  return -1;
}

registry::Components Parts() {
  registry::Components components;
  registry::RegisterBuiltins(components);
  RegisterExampleParts(components);
  return components;
}

TEST(TravelSpan, ItsOptionsAreListedWithTheirDefaults) {
  const registry::Components components = Parts();
  const registry::PartOptions* options = components.triggers.OptionsOf("travel_span");
  ASSERT_NE(options, nullptr);
  ASSERT_NE(options->Find("span_m"), nullptr);
  EXPECT_EQ(options->Find("span_m")->default_value, 10.0);
  std::string why;
  EXPECT_FALSE(options->check({{"span_m", 0.0}}, &why));
  EXPECT_EQ(why, "span_m must be > 0");
}

TEST(TravelSpan, FiresOnceThePositionsSpanWhatItsOptionAsks) {
  const registry::Components components = Parts();
  for (const double span_m : {10.0, 15.0}) {
    const int at = FiresAt(Chain(components, span_m == 10.0 ? schema::PartOptionValues{}  // the default
                                                            : schema::PartOptionValues{{"span_m", span_m}}));
    ASSERT_GT(at, 0) << span_m;
    EXPECT_GE(SpanAfter(at), span_m);
    EXPECT_LT(SpanAfter(at - 1), span_m);
  }
  // A height the path never reaches: it never fires.
  EXPECT_EQ(FiresAt(Chain(components, {{"vertical_span_m", 1.5}})), -1);
}

TEST(TravelSpan, SaysHowFarTheTagStillHasToGo) {
  estimator::AnchorInitializer chain = Chain(Parts(), {{"span_m", 25.0}});
  for (int i = 0; i < 6; ++i) {
    const Eigen::Vector3d p_world_tag = PathAt(i);
    chain.Feed({static_cast<double>(i), 0, 0, p_world_tag.norm(), p_world_tag});
  }
  const std::optional<estimator::Judgement> why = chain.why_not();
  ASSERT_TRUE(why.has_value());
  EXPECT_EQ(why->blocked_by, "travel_span");
  EXPECT_DOUBLE_EQ(why->value, SpanAfter(5));
  EXPECT_EQ(why->limit, 25.0);
}

}  // namespace
}  // namespace anchorbench::example_parts
