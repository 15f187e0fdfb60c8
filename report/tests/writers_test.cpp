// The writers of sweep, replay and PDOP-study files: their columns, one line per record, and empty
// cells (or "-") where there is nothing, read back as a user's script would.
#include <gtest/gtest.h>
#include <algorithm>

#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "anchorbench/report/navigation_report.hpp"
#include "anchorbench/report/pdop_study_report.hpp"
#include "anchorbench/report/replay_report.hpp"
#include "anchorbench/report/replay_summary.hpp"
#include "anchorbench/report/run_outputs.hpp"
#include "anchorbench/report/summary.hpp"
#include "anchorbench/report/sweep_report.hpp"

namespace anchorbench::report {
namespace {

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> Fields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1) {
    fields.push_back(line.substr(start, comma - start));
  }
  fields.push_back(line.substr(start));
  return fields;
}

schema::RowConfig Row(const std::string& name) { return {name, {}, {}, std::nullopt}; }

MethodSummary Summary(int row, const std::string& method, int init, std::optional<double> avg_m) {
  MethodSummary s;
  s.row = row;
  s.method = method;
  s.attempts = 10;
  s.init = init;
  s.avg_m = avg_m;
  s.med_m = avg_m;
  return s;
}

std::vector<SweepPointResult> TwoPoints() {
  const std::vector<schema::RowConfig> rows = {Row("a"), Row("b")};
  std::vector<SweepPointResult> results;
  for (const char* value : {"0.5", "2"}) {
    results.push_back({{{value}, {std::string("estimator.trigger.pdop_threshold=") + value}},
                       rows,
                       {Summary(0, "fixed_window", 10, 0.25), Summary(1, "pdop_closest_point", 0, std::nullopt)}});
  }
  return results;
}

TEST(SweepFiles, OneLinePerPointRowAndMethodUnderTheAxesAndTheSummaryColumns) {
  const std::vector<schema::SweepAxis> axes = {{"estimator.trigger.pdop_threshold", {"0.5", "2"}}};
  std::ostringstream csv, timing;
  WriteSweepCsv(csv, axes, TwoPoints());
  WriteSweepTiming(timing, axes, TwoPoints());
  const std::vector<std::string> lines = Lines(csv.str());
  ASSERT_EQ(lines.size(), 5u);  // the header, 2 points x 2 summaries
  EXPECT_EQ(lines[0], std::string("estimator.trigger.pdop_threshold,") + kSummaryColumns);
  const std::vector<std::string> header = Fields(lines[0]);
  for (std::size_t l = 1; l < lines.size(); ++l) {
    const std::vector<std::string> fields = Fields(lines[l]);
    ASSERT_EQ(fields.size(), header.size()) << lines[l];
    EXPECT_EQ(fields[0], l <= 2 ? "0.5" : "2");
  }
  EXPECT_EQ(Lines(timing.str()).size(), 5u);
  EXPECT_EQ(Lines(timing.str())[0], std::string("estimator.trigger.pdop_threshold,") + kTimingColumns);
}

TEST(SweepFiles, TheMarkdownHasARowPerLineAndADashWhereNothingInitialized) {
  const std::vector<schema::SweepAxis> axes = {{"estimator.trigger.pdop_threshold", {"0.5", "2"}}};
  std::ostringstream md;
  WriteSweepMarkdown(md, "sweep_pdop", 20, 3, axes, TwoPoints());
  const std::string text = md.str();
  EXPECT_NE(text.find("20 realizations per point and row, seed 3."), std::string::npos);
  EXPECT_NE(text.find("| 0.5 | a | fixed_window | 0.250 | 0.250 | 10 | 0 | - | - |\n"), std::string::npos) << text;
  EXPECT_NE(text.find("| 2 | b | pdop_closest_point | - | - | 0 | 0 | - | - |\n"), std::string::npos) << text;
  EXPECT_NE(text.find("Latency: t_init over t_oracle"), std::string::npos) << text;
}

TEST(SweepFiles, TheLatencyCellIsTheMedianAndThe90thPercentileOverTheOracle) {
  MethodSummary s = Summary(0, "certified", 10, 0.25);
  EXPECT_EQ(LatencyCell(s), "-");  // no attempt the oracle reaches
  s.latency_med = 1.654;
  s.latency_p90 = 2.3;
  EXPECT_EQ(LatencyCell(s), "1.65x (2.30x)");
  std::vector<SweepPointResult> point = TwoPoints();
  point.resize(1);
  point[0].summaries = {s};
  std::ostringstream md;
  WriteSweepMarkdown(md, "sweep_pdop", 20, 3, {{"estimator.trigger.pdop_threshold", {"0.5"}}}, point);
  EXPECT_NE(md.str().find("| 0.5 | a | certified | 0.250 | 0.250 | 10 | 0 | - | 1.65x (2.30x) |\n"), std::string::npos)
      << md.str();
}

TEST(ReplayFiles, EstimatesLeaveCellsEmptyWithoutAnEstimateOrTheTruth) {
  schema::Attempt waiting;
  waiting.anchor_id = 4;
  waiting.method = "certified";
  waiting.status = "not_triggered";
  schema::Attempt solved;
  solved.anchor_id = 5;
  solved.method = "pdop_closest_point";
  solved.initialized = true;
  solved.t_init_s = 12.5;
  solved.n_used = 300;
  solved.pdop_closest_point = 0.8;
  solved.solve.emplace();
  solved.solve->p_world_anchor = Eigen::Vector3d(1.0, -2.0, 3.5);
  solved.solve->bias_m = 0.1;
  solved.status = "converged";
  std::ostringstream out;
  WriteEstimates(out, {waiting, solved});
  const std::vector<std::string> lines = Lines(out.str());
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(Fields(lines[0]).front(), "anchor_id");
  const std::vector<std::string> w = Fields(lines[1]), s = Fields(lines[2]);
  ASSERT_EQ(w.size(), Fields(lines[0]).size());
  ASSERT_EQ(s.size(), Fields(lines[0]).size());
  EXPECT_EQ(w[0], "4");
  EXPECT_EQ(w[2], "0");
  EXPECT_EQ(w[7], "");  // no x without an estimate
  EXPECT_EQ(w[12], "not_triggered");
  EXPECT_EQ(s[3], "12.5");
  EXPECT_EQ(s[7] + "," + s[8] + "," + s[9], "1,-2,3.5");
  EXPECT_EQ(s[6], "");   // pdop_true: no truth in a replay without anchors
  EXPECT_EQ(s[11], "");  // err_m
}

TEST(ReplayFiles, EstimatesSayWhatAMirrorWaitsForAndWhatTheModelErrorExplains) {
  schema::Attempt waiting;
  waiting.anchor_id = 2;
  waiting.method = "certified";
  waiting.status = "not_triggered";
  estimator::Judgement why = estimator::BlockedBy("mirror", -120.5, 9.2, 30.0, 800);
  why.samples_needed = std::numeric_limits<double>::infinity();
  why.evidence_explained = 310.25;
  waiting.why_not = why;
  schema::Attempt in_region = waiting;
  in_region.why_not = estimator::BlockedBy("region", 1.5, 0.75, 30.0, 800);
  std::ostringstream out;
  WriteEstimates(out, {waiting, in_region});
  const std::vector<std::string> lines = Lines(out.str());
  ASSERT_EQ(lines.size(), 3u);
  const std::vector<std::string> header = Fields(lines[0]), mirror = Fields(lines[1]), region = Fields(lines[2]);
  const auto cell = [&header](const std::vector<std::string>& row, const std::string& column) {
    const auto it = std::find(header.begin(), header.end(), column);
    return it == header.end() ? std::string("no such column") : row.at(static_cast<std::size_t>(it - header.begin()));
  };
  EXPECT_EQ(cell(mirror, "blocked_by") + "," + cell(mirror, "blocked_value") + "," + cell(mirror, "blocked_limit"),
            "mirror,-120.5,9.2");
  EXPECT_EQ(cell(mirror, "samples_needed"), "inf");
  EXPECT_EQ(cell(mirror, "evidence_explained"), "310.25");  // the mirror fits worse by 189.75: the pattern keeps it in
  EXPECT_EQ(cell(region, "blocked_by"), "region");
  EXPECT_EQ(cell(region, "samples_needed"), "");  // no alternative judged: nothing to say
  EXPECT_EQ(cell(region, "evidence_explained"), "");
}

TEST(ReplayFiles, TheSummaryCountsEachDropWithItsFirstLineAsJson) {
  ReplaySummary summary;
  summary.files = {"poses.csv", {"ranges_a.csv", "ranges_b.csv"}};
  summary.pose_rows = 100;
  summary.range_rows = 400;
  summary.samples_by_anchor = {{1, 250}, {2, 140}};
  summary.drops.Count(io::Drop::kRangeNotFinite, 2, "ranges_a.csv", 7);
  summary.drops.Count(io::Drop::kRangeNotFinite, 2, "ranges_a.csv", 9);
  summary.drops.Count(io::Drop::kPoseJump, 0, "poses.csv", 41);
  std::ostringstream out;
  WriteReplaySummaryJson(out, summary);
  const nlohmann::json json = nlohmann::json::parse(out.str());
  EXPECT_EQ(json["ranges"].size(), 2u);
  EXPECT_EQ(json["samples"], 390);
  EXPECT_EQ(json["dropped"], 3);
  EXPECT_EQ(json["samples_by_anchor"]["1"], 250);
  EXPECT_EQ(json["range_drops_by_anchor"]["2"]["range_not_finite"]["count"], 2);
  EXPECT_EQ(json["range_drops_by_anchor"]["2"]["range_not_finite"]["first"], "ranges_a.csv:7");
  EXPECT_EQ(json["pose_drops_by_tag"]["0"]["pose_jump"]["first"], "poses.csv:41");
  std::ostringstream md;
  WriteReplaySummaryMarkdown(md, summary);
  EXPECT_NE(md.str().find("100 pose rows and 400 range rows read; 390 ranges handed to the initializers; 3 rows dropped"),
            std::string::npos)
      << md.str();
}

TEST(PdopStudyFiles, TheTraceHasALinePerCheckpointAndInfWhereUndefined) {
  schema::PdopCheckpoint c;
  c.realization = 2;
  c.anchor_id = 3;
  c.n = 40;
  c.t_s = 4.0;
  c.pdop = {0.9, std::numeric_limits<double>::infinity(), 1.1, 1.0};
  c.ls_error_m = 0.5;
  std::ostringstream out;
  WritePdopTrace(out, {c, c});
  const std::vector<std::string> lines = Lines(out.str());
  ASSERT_EQ(lines.size(), 3u);
  const std::vector<std::string> header = Fields(lines[0]), fields = Fields(lines[1]);
  ASSERT_EQ(fields.size(), header.size());
  EXPECT_EQ(header[5], "pdop_ls");
  EXPECT_EQ(fields[5], "inf");
  EXPECT_EQ(fields[9], "0.5");  // ls_err_m
  EXPECT_EQ(fields[10], "");    // nls_err_m: the NLS did not run
}

TEST(NavigationFiles, TheErrorOverTimeAveragesTheRealizationsThatHaveABin) {
  const double gap = std::numeric_limits<double>::quiet_NaN();
  auto record = [](int realization, const std::string& method, std::vector<double> bins) {
    nav::NavigationRecord r;
    r.realization = realization;
    r.method = method;
    r.outcome.error_by_bin_m = std::move(bins);
    return r;
  };
  const std::vector<nav::NavigationRecord> records = {record(0, "pdop", {1.0, 2.0, 5.0}), record(0, "none", {3.0}),
                                                      record(1, "pdop", {3.0, gap})};
  std::ostringstream out;
  WriteNavigationErrorCsv(out, records, {Row("a")}, 10.0);
  EXPECT_EQ(out.str(),
            "row,method,t_s,runs,error_mean_m,error_p90_m\n"
            "a,pdop,5,2,2,2.8\n"   // the two realizations' first bins (p90 interpolated)
            "a,pdop,15,1,2,2\n"    // realization 1 has a gap there
            "a,pdop,25,1,5,5\n"    // and ended before
            "a,none,5,1,3,3\n");
}

TEST(NavigationFiles, WorseThanTheDriftIsCountedInPairsOfOneRealization) {
  auto record = [](int realization, const std::string& method, double rmse_m) {
    nav::NavigationRecord r;
    r.realization = realization;
    r.method = method;
    r.outcome.rmse_m = rmse_m;
    return r;
  };
  // Realization 0 drifts little, 1 much: the trigger's 0.5 m is worse in the first alone.
  const std::vector<NavigationSummary> summaries = SummarizeNavigation(
      {record(0, "pdop", 0.5), record(0, "none", 0.3), record(1, "pdop", 0.5), record(1, "none", 3.0)}, 1, 0, 1, "none");
  ASSERT_EQ(summaries.size(), 2u);
  EXPECT_EQ(summaries[0].worse_than_drift, 1);
  EXPECT_FALSE(summaries[1].worse_than_drift.has_value());  // the drift itself
  std::ostringstream markdown;
  schema::ExperimentConfig config;
  WriteNavigationMarkdown(markdown, summaries, {Row("a")}, config);
  EXPECT_NE(markdown.str().find("| a | pdop | 0.500 | 0.000 | 0.0 | - | - | 50 |"), std::string::npos) << markdown.str();
}

}  // namespace
}  // namespace anchorbench::report
