#include "anchorbench/schema/sweep.hpp"

#include <gtest/gtest.h>

#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::schema {

namespace {

using Values = std::vector<std::string>;

TEST(Sweep, ListsAndInclusiveRanges) {
  EXPECT_EQ(ParseSweepAxis("k", "0.5, 1,2").values, (Values{"0.5", "1", "2"}));
  EXPECT_EQ(ParseSweepAxis("k", "0.1:0.3:0.1").values, (Values{"0.1", "0.2", "0.3"}));  // no 0.30000000000000004
  const SweepAxis pdop = ParseSweepAxis("k", "0.25:3:0.25");
  ASSERT_EQ(pdop.values.size(), 12u);
  EXPECT_EQ(pdop.values.back(), "3");
  EXPECT_EQ(ParseSweepAssignment("scenario.ranging.outlier_kind=positive,symmetric").values,
            (Values{"positive", "symmetric"}));
  EXPECT_EQ(ParseSweepAssignment("estimator.solver=lm_adaptive,nlopt:LN_BOBYQA").values,
            (Values{"lm_adaptive", "nlopt:LN_BOBYQA"}));  // a name with ':' is not a range
}

TEST(Sweep, BadValuesNameTheKey) {
  EXPECT_THROW(ParseSweepAxis("a.b", "1:2"), schema::InputError);
  EXPECT_THROW(ParseSweepAxis("a.b", "1:0:0.5"), schema::InputError);
  EXPECT_THROW(ParseSweepAxis("a.b", "1:2:0"), schema::InputError);
  EXPECT_THROW(ParseSweepAxis("a.b", "1:x:1"), schema::InputError);  // starts like a range, is not one
  EXPECT_THROW(ParseSweepAxis("a.b", "1,,2"), schema::InputError);
  EXPECT_THROW(ParseSweepAssignment("no_equals"), schema::InputError);
  try {
    ParseSweepAxis("estimator.trigger.pdop_threshold", "0:1:-1");
  } catch (const schema::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("estimator.trigger.pdop_threshold"), std::string::npos);
  }
}

TEST(Sweep, GridIsTheProductFirstAxisSlowest) {
  const auto grid = SweepGrid({ParseSweepAxis("a", "1,2"), ParseSweepAxis("b", "x,y,z")});
  ASSERT_EQ(grid.size(), 6u);
  EXPECT_EQ(grid[0].overrides, (Values{"a=1", "b=x"}));
  EXPECT_EQ(grid[2].overrides, (Values{"a=1", "b=z"}));
  EXPECT_EQ(grid[3].overrides, (Values{"a=2", "b=x"}));
  EXPECT_EQ(grid[3].values, (Values{"2", "x"}));
}

TEST(Sweep, AxesFromTheCommandLineReplaceTheConfigsOfTheSameKey) {
  const auto axes = SweepAxes({{"a", "1,2"}, {"b", "x"}}, {"b=y,z", "c=0:1:1"});
  ASSERT_EQ(axes.size(), 3u);
  EXPECT_EQ(axes[1].values, (Values{"y", "z"}));
  EXPECT_EQ(DescribeAxes(axes), (Values{"a=1,2", "b=y,z", "c=0,1"}));
}

}  // namespace
}  // namespace anchorbench::schema
