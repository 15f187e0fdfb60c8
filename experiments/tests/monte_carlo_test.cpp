#include "anchorbench/experiments/monte_carlo.hpp"

#include <sstream>

#include <gtest/gtest.h>

#include "anchorbench/experiments/run_outputs.hpp"
#include "anchorbench/experiments/summary.hpp"

namespace anchorbench::experiments {
namespace {

// A small two-row table: a short tunnel, a few anchors, a mix of trajectories.
ExperimentConfig SmallTable() {
  ExperimentConfig config;
  config.name = "small";
  config.seed = 7;
  config.realizations = 6;
  config.bootstrap_resamples = 200;
  config.scenario.tunnel.length_m = 60.0;
  config.scenario.tunnel.num_anchors = 4;
  config.scenario.trajectory.fraction_straight = 0.2;
  config.scenario.trajectory.fraction_planar = 0.2;
  config.scenario.ranging.outlier_probability = 0.05;
  config.scenario.ranging.sigma_position_m = 0.02;
  RowConfig low{"low", config.scenario, config.estimator, std::nullopt};
  RowConfig high = low;
  high.name = "high";
  high.scenario.ranging.sigma_range_m = 0.4;
  config.rows = {low, high};
  return config;
}

std::string Outputs(const ExperimentConfig& config, int threads) {
  const std::vector<Attempt> attempts = RunMonteCarlo(config, {threads, nullptr});
  const auto rows = RowsOf(config);
  const auto summaries = Summarize(attempts, rows, config.realizations, config.bootstrap_resamples, config.seed);
  std::ostringstream out;
  WriteAttempts(out, attempts, rows);
  WriteSummaryCsv(out, summaries, rows);
  WriteSummaryMarkdown(out, summaries, rows, config);
  return out.str();
}

TEST(MonteCarlo, BitIdenticalForAnyThreadCount) {
  const ExperimentConfig config = SmallTable();
  const std::string one = Outputs(config, 1);
  EXPECT_EQ(one, Outputs(config, 2));
  EXPECT_EQ(one, Outputs(config, 3));  // more threads than cores, uneven split
}

// Every trigger and filter on the same trials, with RANSAC and a stochastic part seeded per anchor.
TEST(MonteCarlo, AllTriggersAndFiltersAreBitIdenticalForAnyThreadCount) {
  ExperimentConfig config = SmallTable();
  config.realizations = 3;
  const std::vector<std::string> triggers = {"pdop_closest_point", "pdop_ls", "pdop_nls", "pdop_true",
                                             "fixed_window", "sample_count", "timeout"};
  for (RowConfig& row : config.rows) {
    row.estimator.triggers = triggers;
    row.estimator.solver_name = "lm_l2";
    row.estimator.filter.kind = "ransac";
    row.estimator.filter.ransac.subset_size = 20;  // 20 subsets: a quick RANSAC
    row.estimator.filter.ransac.outlier_fraction = 0.1;
    row.estimator.filter.ransac.success_probability = 0.9;
  }
  const std::string one = Outputs(config, 1);
  EXPECT_EQ(one, Outputs(config, 2));
  const std::vector<Attempt> attempts = RunMonteCarlo(config, {2, nullptr});
  ASSERT_EQ(attempts.size(), 2u * 3u * 4u * triggers.size());
  for (std::size_t i = 0; i < attempts.size(); ++i) {
    EXPECT_EQ(attempts[i].method, triggers[i % triggers.size()]);  // anchor by anchor, in list order
    EXPECT_GE(attempts[i].compute_s, 0.0);
  }
}

TEST(MonteCarlo, EveryAnchorIsOneAttemptPerStrategyAndNothingIsNan) {
  const ExperimentConfig config = SmallTable();
  const std::vector<Attempt> attempts = RunMonteCarlo(config, {2, nullptr});
  ASSERT_EQ(attempts.size(), 2u * 6u * 4u * 2u);  // rows x realizations x anchors x strategies
  for (const Attempt& a : attempts) {
    EXPECT_FALSE(a.status.empty());
    if (a.initialized) {
      ASSERT_TRUE(a.error_m.has_value());
      EXPECT_TRUE(std::isfinite(*a.error_m));
    } else {
      EXPECT_FALSE(a.error_m.has_value());
    }
  }
  const std::string text = Outputs(config, 2);
  EXPECT_EQ(text.find("nan"), std::string::npos);
}

TEST(MonteCarlo, ExactlyStraightRunsRecordDegenerateStatusesAndNeverAbort) {
  ExperimentConfig config = SmallTable();
  for (RowConfig& row : config.rows) {
    row.scenario.trajectory.fraction_straight = 1.0;
    row.scenario.trajectory.fraction_planar = 0.0;
    row.scenario.ranging.sigma_position_m = 0.0;  // exactly collinear tag positions
  }
  const std::vector<Attempt> attempts = RunMonteCarlo(config, {1, nullptr});
  int degenerate = 0;
  for (const Attempt& a : attempts) {
    if (a.method == kPaperTrigger) {
      EXPECT_FALSE(a.initialized);  // the PDOP of a straight line is infinite
    }
    degenerate += a.status == "degenerate_geometry";
  }
  EXPECT_GT(degenerate, 0);
  EXPECT_EQ(Outputs(config, 1).find("nan"), std::string::npos);
}

TEST(MonteCarlo, TheConfiguredSolverIsTheOneThatRuns) {
  ExperimentConfig config = SmallTable();
  config.rows.resize(1);
  const std::vector<Attempt> adaptive = RunMonteCarlo(config, {1, nullptr});
  config.rows[0].estimator.solver_name = "ls_double";  // closed form: no kernel, alpha stays 2
  const std::vector<Attempt> ls = RunMonteCarlo(config, {1, nullptr});
  ASSERT_EQ(adaptive.size(), ls.size());
  int differ = 0;
  for (std::size_t i = 0; i < ls.size(); ++i) {
    if (ls[i].alpha) {
      EXPECT_EQ(*ls[i].alpha, 2.0);
    }
    differ += adaptive[i].error_m != ls[i].error_m;
  }
  EXPECT_GT(differ, 0);
}

Attempt Initialized(int realization, double error_m) {
  Attempt a;
  a.realization = realization;
  a.method = kFixedWindowTrigger;
  a.initialized = true;
  a.error_m = error_m;
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
  const auto summaries = Summarize(attempts, {RowConfig{}}, 2, 500, 1);  // default triggers
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
  // No gated attempts at all: the cells stay empty, never NaN.
  EXPECT_EQ(summaries[1].init, 0);
  EXPECT_FALSE(summaries[1].avg_m.has_value());
  EXPECT_FALSE(summaries[1].ratio_pct.has_value());
}

TEST(Summary, ManifestNamesWhatReproducesTheRun) {
  const std::string json = ManifestJson(SmallTable(), {"configs/small.yaml", 2, 1.25, {}});
  for (const char* key : {"\"seed\": 7", "\"threads\": 2", "\"realizations\": 6", "\"git_revision\"", "\"compiler\"",
                          "\"wall_time_s\": 1.250", "\"resolved_config\"", "\"sigma_range_m\": 0.4"}) {
    EXPECT_NE(json.find(key), std::string::npos) << key;
  }
}

}  // namespace
}  // namespace anchorbench::experiments
