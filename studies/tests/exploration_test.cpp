#include "anchorbench/studies/exploration.hpp"

#include <functional>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "anchorbench/studies/exploration_lines.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/testing/temp_dir.hpp"
#include "anchorbench/testing/components.hpp"

namespace anchorbench::studies {
namespace {

using engine::ChunkStore;
using engine::RecordJournal;

using testing::AllComponents;

// configs/exploration_uav_hall.yaml's flat row, shorter: a drone surveying a small hall at one
// height, where the certificate waits for the mirror through the path's plane.
schema::ExperimentConfig FlatSurvey() {
  schema::ExperimentConfig config;
  config.name = "flat_survey";
  config.realizations = 3;
  sim::ScenarioOptions& s = config.scenario;
  s.environment = sim::EnvironmentKind::kHall;
  s.hall.length_m = 6.5;
  s.hall.width_m = 4.0;
  s.hall.height_m = 7.0;
  s.hall.num_anchors = 4;
  s.hall.anchor_height_min_m = 0.5;
  s.hall.anchor_height_max_m = 6.0;
  s.trajectory.kind = sim::TrajectoryKind::kPlanar;
  s.trajectory.height_m = 3.5;
  s.trajectory.hall_duration_s = 120.0;
  s.trajectory.min_period_s = 30.0;
  s.trajectory.max_period_s = 120.0;
  s.ranging.sigma_range_m = 0.1;
  s.ranging.bias_a_m = -0.3;
  s.ranging.bias_b_m = 0.3;
  // Motion capture's 5 mm: with exact poses on an exact plane the solve refuses (the height is not
  // in the data at all), so no estimate has a region to forecast (docs/guidance.md).
  s.ranging.sigma_position_m = 0.005;
  config.estimator.triggers = {"certified"};
  config.exploration.emplace();
  config.exploration->max_duration_s = 200.0;
  return config;
}

TEST(Exploration, EveryPolicyForEachRealizationTheSameOnAnyThreads) {
  const schema::ExperimentConfig config = FlatSurvey();
  const std::vector<ExplorationRecord> one = RunExploration(config, AllComponents(), 1);
  const std::vector<ExplorationRecord> three = RunExploration(config, AllComponents(), 3);
  ASSERT_EQ(one.size(), 3u * 2u);
  ASSERT_EQ(three.size(), one.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].realization, static_cast<int>(i / 2));
    EXPECT_EQ(one[i].policy, i % 2 == 0 ? schema::kPatternPolicy : schema::kGuidedPolicy);
    EXPECT_EQ(one[i].policy, three[i].policy);
    EXPECT_EQ(one[i].certified, three[i].certified);
    EXPECT_EQ(one[i].distance_m, three[i].distance_m) << i;  // bit for bit
    EXPECT_EQ(one[i].t_all_certified_s, three[i].t_all_certified_s) << i;
  }
}

TEST(Exploration, GuidanceCertifiesWhatAFlatSurveyCannot) {
  schema::ExperimentConfig config = FlatSurvey();
  config.exploration->policies = {schema::kPatternPolicy, schema::kGuidedPolicy, schema::kOraclePolicy,
                                  schema::kDopWaypointsPolicy};
  std::map<std::string, int> certified;
  for (const ExplorationRecord& r : RunExploration(config, AllComponents(), 2)) {
    EXPECT_EQ(r.anchors, 4);
    EXPECT_EQ(r.beyond_accuracy, 0) << r.policy << " " << r.realization;
    EXPECT_GT(r.distance_m, 0.0);
    if (r.policy == schema::kPatternPolicy) {
      EXPECT_EQ(r.detours, 0);
    } else {
      EXPECT_GT(r.detours, 0) << r.policy;
    }
    certified[r.policy] += r.certified;
  }
  // The flat survey's height is unobservable: the certificate refuses; the detours leave the plane.
  EXPECT_EQ(certified[schema::kPatternPolicy], 0);
  EXPECT_GE(certified[schema::kGuidedPolicy], 10);  // of 12
  EXPECT_GE(certified[schema::kOraclePolicy], 10);
  EXPECT_GE(certified[schema::kDopWaypointsPolicy], 10);
}

TEST(Exploration, WithANavigationSectionEveryRunIsNavigatedOverTheSameTime) {
  schema::ExperimentConfig config = FlatSurvey();
  config.navigation.emplace();
  double pattern_m = 0.0, guided_m = 0.0;
  for (const ExplorationRecord& r : RunExploration(config, AllComponents(), 2)) {
    EXPECT_EQ(r.duration_s, config.exploration->max_duration_s);  // not cut at the last certification
    ASSERT_GE(r.navigation_rmse_m, 0.0);
    (r.policy == schema::kPatternPolicy ? pattern_m : guided_m) += r.navigation_rmse_m;
  }
  // The survey alone certifies no anchor: odometry alone drifts; guidance's anchors hold it.
  EXPECT_LT(guided_m, 0.5 * pattern_m);
  for (const ExplorationRecord& r : RunExploration(FlatSurvey(), AllComponents(), 2)) EXPECT_EQ(r.navigation_rmse_m, -1.0);
}

TEST(Exploration, AGroundRobotKeepsItsHeightAndCannotLeaveThePlane) {
  schema::ExperimentConfig config = FlatSurvey();
  config.exploration->policies = {schema::kGuidedPolicy};
  config.exploration->vertical = false;
  for (const ExplorationRecord& r : RunExploration(config, AllComponents(), 2)) EXPECT_EQ(r.certified, 0);
}

// The offline waypoints' grid over a 10 km tunnel at 1 mm steps would hold ~1e15 points: it is
// coarsened to at most 1e5, so the plan is made (the old grid never finished).
TEST(Exploration, AHugeEnvironmentWithAFineReachPlansOnABoundedGrid) {
  schema::ExperimentConfig config = FlatSurvey();
  config.realizations = 1;
  config.scenario.environment = sim::EnvironmentKind::kTunnel;
  config.scenario.tunnel.length_m = 10000.0;
  config.scenario.tunnel.num_anchors = 4;
  config.scenario.trajectory.kind = sim::TrajectoryKind::kRandom;
  config.exploration->policies = {schema::kDopWaypointsPolicy};
  config.exploration->reach_m = 0.01;
  config.exploration->grid_steps = 10;
  config.exploration->plan_after_s = 0.0;
  config.exploration->max_duration_s = 2.0;
  const std::vector<ExplorationRecord> records = RunExploration(config, AllComponents(), 1);
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0].duration_s, 2.0);
}

// The summary's paired ratio: each realization's time over the pattern's, over the realizations
// the pattern certifies whole; a policy's run that never does counts +inf.
TEST(Exploration, TheSummaryPairsEachPolicysTimeWithThePatternsOnTheSameRealization) {
  const schema::ExperimentConfig config = FlatSurvey();
  std::vector<ExplorationRecord> records;
  auto add = [&records](int realization, const char* policy, double t_all_s) {
    ExplorationRecord r;
    r.realization = realization;
    r.policy = policy;
    r.anchors = 4;
    r.t_all_certified_s = t_all_s;
    records.push_back(r);
  };
  // Guided over the pattern: 40/100, 30/50, never/80, and a realization the pattern never completes.
  add(0, schema::kPatternPolicy, 100.0), add(0, schema::kGuidedPolicy, 40.0);
  add(1, schema::kPatternPolicy, 50.0), add(1, schema::kGuidedPolicy, 30.0);
  add(2, schema::kPatternPolicy, 80.0), add(2, schema::kGuidedPolicy, -1.0);
  add(3, schema::kPatternPolicy, -1.0), add(3, schema::kGuidedPolicy, 1.0);
  std::map<std::string, std::string> files;
  WriteExplorationFiles([&files](const std::string& name, const std::function<void(std::ostream&)>& write) {
    std::ostringstream out;
    write(out);
    files[name] = out.str();
  }, config, records, {});
  const std::string& summary = files.at("exploration_summary.csv");
  // One row, "base" (RowsOf a config without rows): the medians of {0.4, 0.6, inf}, and none for
  // the pattern against itself.
  EXPECT_NE(summary.find("base,guided,4,3,35.0,16,0,0,0.600,"), std::string::npos) << summary;
  EXPECT_NE(summary.find("base,pattern,4,3,90.0,16,0,0,,"), std::string::npos) << summary;
}

// A killed run's journal: its units read back as they were computed (navigation bins included), a
// unit edited so that its checksum fits but its counts are impossible is computed again, and the
// whole comes out as the uninterrupted run's records.
TEST(Exploration, AResumedRunTakesItsJournalsUnitsAndRecomputesTheRest) {
  const testing::TempDir dir("exploration_journal");
  schema::ExperimentConfig config = FlatSurvey();
  config.navigation.emplace();
  const std::vector<ExplorationRecord> whole = RunExploration(config, AllComponents(), 2);
  const std::size_t policies = config.exploration->policies.size();
  const auto unit_records = [&](std::size_t unit) {
    return std::vector<ExplorationRecord>(whole.begin() + static_cast<long>(unit * policies),
                                          whole.begin() + static_cast<long>((unit + 1) * policies));
  };
  const std::string text = ExplorationUnitText(unit_records(0));
  const std::vector<ExplorationRecord> read = ReadExplorationUnit(text, {"journal", 1}, 0, 0, config.exploration->policies);
  EXPECT_EQ(ExplorationUnitText(read), text);  // round-trip precision
  EXPECT_THROW(ReadExplorationUnit(text, {"journal", 1}, 0, 1, config.exploration->policies), schema::InputError);
  const long long units = static_cast<long long>(whole.size() / policies);
  {
    RecordJournal killed(dir.path() / "out", "explore", units, ChunkStore::Mode::kFresh);
    killed.Append(0, text);
    std::vector<ExplorationRecord> forged = unit_records(1);
    forged[0].certified = forged[0].anchors + 1;  // no run writes it; the block's checksum is made to fit
    killed.Append(1, ExplorationUnitText(forged));
  }
  RecordJournal journal(dir.path() / "out", "explore", units, ChunkStore::Mode::kResume);
  const std::vector<ExplorationRecord> resumed = RunExploration(config, AllComponents(), 2, {}, &journal);
  EXPECT_EQ(journal.unreadable(), 1);
  EXPECT_NE(journal.first_unreadable().find("more certified than anchors"), std::string::npos) << journal.first_unreadable();
  EXPECT_EQ(ExplorationUnitText(resumed), ExplorationUnitText(whole));
}

TEST(Exploration, AConfigWithoutAnExplorationSectionIsRefused) {
  schema::ExperimentConfig config = FlatSurvey();
  config.exploration.reset();
  EXPECT_THROW(RunExploration(config, AllComponents(), 1), schema::InputError);
}

}  // namespace
}  // namespace anchorbench::studies
