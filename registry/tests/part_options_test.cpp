// A part that owns its options: the registry describes them from the part's struct, checks a
// config's values with the part's own rule, and builds the part from them.
#include "anchorbench/registry/part_options.hpp"

#include <gtest/gtest.h>

#include "anchorbench/estimator/triggers.hpp"
#include "anchorbench/registry/components.hpp"

namespace anchorbench::registry {
namespace {

struct CountOptions {
  int count = 40;
  double scale = 1.5;
  bool IsValid(std::string* why) const {
    if (count * scale > 1000.0) {
      if (why) *why = "count times scale must be at most 1000";
      return false;
    }
    return true;
  }
};

template <typename V>
void VisitOptions(V& v, CountOptions& o) {
  v.Integer("count", o.count, "samples before it fires");
  v.Number("scale", o.scale, "a factor");
}

Components WithCountTrigger(int* built_count) {
  Components components;
  RegisterBuiltins(components);
  components.triggers.RegisterWithOptions<CountOptions>(
      "my_count", "fires after count samples", [built_count](const CountOptions& options, const TriggerContext&) {
        *built_count = options.count;
        return std::make_unique<estimator::SampleCountTrigger>(options.count);
      });
  return components;
}

TEST(PartOptions, TheRegistryDescribesAPartsOptionsFromItsStruct) {
  int built = 0;
  const Components components = WithCountTrigger(&built);
  const PartOptions* options = components.triggers.OptionsOf("my_count");
  ASSERT_NE(options, nullptr);
  ASSERT_EQ(options->specs.size(), 2u);
  EXPECT_EQ(options->specs[0].key, "count");
  EXPECT_EQ(options->specs[0].default_value, 40.0);
  EXPECT_TRUE(options->specs[0].whole);
  EXPECT_EQ(options->specs[1].description, "a factor");
  EXPECT_EQ(components.triggers.OptionsOf("pdop_closest_point"), nullptr);  // a built-in owns none
  const auto parts = components.PartsWithOptions();
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0].first, "my_count");
}

TEST(PartOptions, ValuesAreCheckedWholeWhereTheFieldIsAnIntegerAndByThePartsOwnRule) {
  int built = 0;
  const Components components = WithCountTrigger(&built);
  const PartOptions* options = components.triggers.OptionsOf("my_count");
  ASSERT_NE(options, nullptr);
  std::string why;
  EXPECT_TRUE(options->check({{"count", 100.0}}, &why)) << why;
  EXPECT_FALSE(options->check({{"count", 2.5}}, &why));
  EXPECT_EQ(why, "count must be a whole number");
  EXPECT_FALSE(options->check({{"count", 1000.0}}, &why));  // 1000 * the default scale 1.5
  EXPECT_EQ(why, "count times scale must be at most 1000");
  EXPECT_TRUE(options->check({{"count", 1000.0}, {"scale", 1.0}}, &why)) << why;
}

TEST(PartOptions, TheFactoryGetsTheConfigsValuesOverTheDefaults) {
  int built = 0;
  const Components components = WithCountTrigger(&built);
  schema::EstimatorConfig config;
  config.triggers = {"my_count"};
  MakeChains(components, 0, config, 1);
  EXPECT_EQ(built, 40);  // nothing set: the struct's default
  config.part_options["my_count"] = {{"count", 7.0}};
  MakeChains(components, 0, config, 1);
  EXPECT_EQ(built, 7);
}

}  // namespace
}  // namespace anchorbench::registry
