#include "anchorbench/report/summary.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "anchorbench/testing/paper_estimator.hpp"

#include "anchorbench/report/run_outputs.hpp"

namespace anchorbench::report {
namespace {

using schema::Attempt;
using schema::kFixedWindowTrigger;
using schema::RowConfig;

Attempt Initialized(int realization, double error_m) {
  Attempt a;
  a.realization = realization;
  a.method = kFixedWindowTrigger;
  a.initialized = true;
  a.evaluation = schema::AttemptEvaluation{};
  a.evaluation->error_m = error_m;
  a.status = "converged";
  return a;
}

TEST(Summary, TableColumnsWorkedByHand) {
  // Errors 0.1, 0.2, 0.3, 2.0 (initialized) and one attempt not initialized:
  // Avg = 2.6 / 4 = 0.65, Med = (0.2 + 0.3) / 2 = 0.25, Init = 4, >1m = 1, Ratio = 25%.
  std::vector<Attempt> attempts = {Initialized(0, 0.1), Initialized(0, 0.2), Initialized(1, 0.3), Initialized(1, 2.0)};
  Attempt missed;
  missed.realization = 1;
  missed.method = kFixedWindowTrigger;
  missed.status = "too_few_samples";
  attempts.push_back(missed);
  RowConfig row;
  row.estimator = anchorbench::testing::PaperEstimator();  // its two triggers
  const auto summaries = Summarize(attempts, {row}, 2, 500, 1);
  ASSERT_EQ(summaries.size(), 2u);  // fixed_window, then pdop_closest_point
  const MethodSummary& fixed = summaries[0];
  EXPECT_EQ(fixed.attempts, 5);
  EXPECT_EQ(fixed.init, 4);
  EXPECT_NEAR(*fixed.avg_m, 0.65, 1e-12);
  EXPECT_NEAR(*fixed.med_m, 0.25, 1e-12);
  EXPECT_EQ(fixed.gt1m, 1);
  EXPECT_NEAR(*fixed.ratio_pct, 25.0, 1e-12);
  // Resampling the two realizations: Avg is 0.15 (realization 0 twice), 0.65 or 1.15.
  EXPECT_NEAR(*fixed.avg_lo, 0.15, 1e-12);
  EXPECT_NEAR(*fixed.avg_hi, 1.15, 1e-12);
  // Med from the same resamples: 0.15 (realization 0 twice), 0.25 or 1.15 (realization 1 twice).
  EXPECT_NEAR(*fixed.med_lo, 0.15, 1e-12);
  EXPECT_NEAR(*fixed.med_hi, 1.15, 1e-12);
  // No gated attempts at all: the cells stay empty, never NaN.
  EXPECT_EQ(summaries[1].init, 0);
  EXPECT_FALSE(summaries[1].avg_m.has_value());
  EXPECT_FALSE(summaries[1].ratio_pct.has_value());
}

// A method's bootstrap interval depends on its own attempts only: another trigger in front of it
// in the config does not move it.
TEST(Summary, AddingATriggerLeavesTheOthersIntervalsAlone) {
  std::vector<Attempt> attempts;
  for (int r = 0; r < 10; ++r) attempts.push_back(Initialized(r, 0.1 * (r + 1)));
  RowConfig alone, behind;
  alone.estimator.triggers = {kFixedWindowTrigger};
  behind.estimator.triggers = {"pdop_closest_point", kFixedWindowTrigger};
  const auto a = Summarize(attempts, {alone}, 10, 200, 3);
  const auto b = Summarize(attempts, {behind}, 10, 200, 3);
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(*a[0].avg_lo, *b[1].avg_lo);
  EXPECT_EQ(*a[0].avg_hi, *b[1].avg_hi);
  EXPECT_LT(*a[0].avg_lo, *a[0].avg_hi);
}

// Wilson's interval, against values worked by hand (z = 1.96): 0 of 10 gives [0, 0.2775], 5 of 10
// [0.2366, 0.7634]; never outside [0, 1], absent without trials.
TEST(Summary, WilsonIntervalIsMeaningfulAtZero) {
  const Interval none = *WilsonInterval(0, 10);
  EXPECT_DOUBLE_EQ(none.lo, 0.0);
  EXPECT_NEAR(none.hi, 0.2775, 1e-4);
  const Interval half = *WilsonInterval(5, 10);
  EXPECT_NEAR(half.lo, 0.2366, 1e-4);
  EXPECT_NEAR(half.hi, 0.7634, 1e-4);
  const Interval all = *WilsonInterval(10, 10);
  EXPECT_NEAR(all.lo, 1.0 - 0.2775, 1e-4);
  EXPECT_DOUBLE_EQ(all.hi, 1.0);
  EXPECT_FALSE(WilsonInterval(0, 0));
  std::vector<Attempt> attempts;
  for (int r = 0; r < 20; ++r) attempts.push_back(Initialized(r, 0.1));
  RowConfig row;
  row.estimator.triggers = {kFixedWindowTrigger};
  const MethodSummary s = Summarize(attempts, {row}, 20, 100, 1)[0];
  EXPECT_EQ(*s.ratio_lo, 0.0);
  EXPECT_NEAR(*s.ratio_hi, 100.0 * 0.1611, 0.01);  // 0 of 20: up to 16%, not [0, 0]
}

TEST(Summary, ManifestNamesWhatReproducesTheRun) {
  schema::ExperimentConfig config;
  config.seed = 7;
  config.realizations = 6;
  RunInfo info;
  info.config_path = "configs/small.yaml";
  info.revision = "abc123";
  info.threads = 2;
  info.wall_time_s = 1.25;
  info.command_line = {"--realizations 6", "--set scenario.ranging.sigma_range_m=0.4"};
  info.sweep_axes = {"estimator.filter.tau_m=0.1,0.2"};
  info.wall_time_s = 1.2504;
  info.resolved_config = {{"seed", 7}};
  info.config_path = "configs/a \"quoted\"\tname\x01.yaml";  // escaped whatever it holds
  const nlohmann::json json = nlohmann::json::parse(ManifestJson(config, info));
  EXPECT_EQ(json["config_file"], info.config_path);
  EXPECT_EQ(json["seed"], 7);
  EXPECT_EQ(json["threads"], 2);
  EXPECT_EQ(json["realizations"], 6);
  EXPECT_EQ(json["git_revision"], "abc123");
  EXPECT_TRUE(json.contains("compiler"));
  EXPECT_EQ(json["wall_time_s"], 1.25);  // to the millisecond
  EXPECT_EQ(json["resolved_config"]["seed"], 7);
  EXPECT_EQ(json["command_line"][1], "--set scenario.ranging.sigma_range_m=0.4");
  EXPECT_EQ(json["sweep_axes"], nlohmann::json::array({"estimator.filter.tau_m=0.1,0.2"}));
}

TEST(Summary, AManifestOfAPathThatIsNotUtf8IsStillJson) {
  RunInfo info;
  info.config_path = "configs/latin1_\xe9.yaml";
  const nlohmann::json json = nlohmann::json::parse(ManifestJson({}, info));
  EXPECT_EQ(json["config_file"], "configs/latin1_\xef\xbf\xbd.yaml");  // U+FFFD
}

TEST(Summary, AManifestOfASeedAbove2To53KeepsItExactly) {
  schema::ExperimentConfig config;
  config.seed = (std::uint64_t{1} << 63) - 1;
  const nlohmann::json json = nlohmann::json::parse(ManifestJson(config, {}));
  EXPECT_EQ(json["seed"].get<std::uint64_t>(), config.seed);
}

TEST(Summary, AttemptsCsvLeavesCellsEmptyWhereThereIsNothing) {
  Attempt a;
  a.method = kFixedWindowTrigger;
  a.status = "no_data";
  std::ostringstream out;
  WriteAttempts(out, {a}, {RowConfig{"r", {}, {}, std::nullopt}});
  EXPECT_EQ(out.str().substr(out.str().find('\n') + 1), "r,0,0,fixed_window,0,,0,0,,,,,,,,,no_data,,,,,,,,,,,,,\n");
}

}  // namespace
}  // namespace anchorbench::report
