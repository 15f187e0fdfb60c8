#include "anchorbench/experiments/sweep.hpp"

#include <gtest/gtest.h>

#include "anchorbench/experiments/config.hpp"
#include "anchorbench/experiments/input_error.hpp"
#include "temp_dir.hpp"

namespace anchorbench::experiments {
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
  EXPECT_THROW(ParseSweepAxis("a.b", "1:2"), InputError);
  EXPECT_THROW(ParseSweepAxis("a.b", "1:0:0.5"), InputError);
  EXPECT_THROW(ParseSweepAxis("a.b", "1:2:0"), InputError);
  EXPECT_THROW(ParseSweepAxis("a.b", "1:x:1"), InputError);  // starts like a range, is not one
  EXPECT_THROW(ParseSweepAxis("a.b", "1,,2"), InputError);
  EXPECT_THROW(ParseSweepAssignment("no_equals"), InputError);
  try {
    ParseSweepAxis("estimator.trigger.pdop_threshold", "0:1:-1");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("estimator.trigger.pdop_threshold"), std::string::npos);
  }
}

TEST(Sweep, GridIsTheProductFirstAxisSlowest) {
  const auto grid = SweepGrid({ParseSweepAxis("a", "1,2"), ParseSweepAxis("b", "x,y,z")});
  ASSERT_EQ(grid.size(), 6u);
  EXPECT_EQ(grid[0], (Values{"a=1", "b=x"}));
  EXPECT_EQ(grid[2], (Values{"a=1", "b=z"}));
  EXPECT_EQ(grid[3], (Values{"a=2", "b=x"}));
}

TEST(ConfigFiles, BaseInheritanceOnlyRowsAndOverridesThatReachRows) {
  testing::TempDir dir("base");
  dir.Write("table.yaml",
            "scenario:\n  tunnel: {width_m: 10}\nestimator:\n  filter: {tau_m: 0.2}\n"
            "rows:\n  - {name: a, estimator: {filter: {tau_m: 0.3}}}\n  - {name: b}\n");
  const std::string derived = dir.Write("derived.yaml",
                                        "base: table.yaml\nrealizations: 7\nonly_rows: [b]\n"
                                        "scenario:\n  tunnel: {height_m: 7}\nsweep:\n  estimator.filter.tau_m: 0.1:0.3:0.1\n");
  const ExperimentConfig config = LoadConfig(derived);
  EXPECT_EQ(config.realizations, 7);
  EXPECT_EQ(config.scenario.tunnel.width_m, 10.0);  // from the base file
  EXPECT_EQ(config.scenario.tunnel.height_m, 7.0);  // merged over it
  ASSERT_EQ(RowsOf(config).size(), 1u);
  EXPECT_EQ(RowsOf(config)[0].name, "b");
  ASSERT_EQ(config.sweep.size(), 1u);
  EXPECT_EQ(config.sweep[0].second, "0.1:0.3:0.1");

  // An override of a base key also replaces the rows' own values of it.
  const ExperimentConfig swept = LoadConfig(derived, {"estimator.filter.tau_m=0.9"});
  EXPECT_EQ(swept.estimator.filter.consistency.tau_m, 0.9);
  EXPECT_EQ(swept.rows[0].estimator.filter.consistency.tau_m, 0.9);  // row a had its own 0.3
  EXPECT_EQ(swept.rows[1].estimator.filter.consistency.tau_m, 0.9);

  const std::string unknown_row = dir.Write("bad.yaml", "base: table.yaml\nonly_rows: [c]\n");
  EXPECT_THROW(LoadConfig(unknown_row), InputError);
  const std::string cycle = dir.Write("cycle.yaml", "base: cycle.yaml\n");
  EXPECT_THROW(LoadConfig(cycle), InputError);
}

}  // namespace
}  // namespace anchorbench::experiments
