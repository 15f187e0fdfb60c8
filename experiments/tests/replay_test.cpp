#include "anchorbench/experiments/replay.hpp"

#include <sstream>

#include <gtest/gtest.h>

#include "anchorbench/experiments/config.hpp"
#include "anchorbench/experiments/input_error.hpp"
#include "anchorbench/experiments/scenario_files.hpp"
#include "temp_dir.hpp"

namespace anchorbench::experiments {
namespace {

// A hall with rich 3D motion, no outliers, exact tag positions: every anchor is well observed.
sim::ScenarioOptions WellConditionedHall() {
  sim::ScenarioOptions o;
  o.environment = sim::EnvironmentKind::kHall;
  o.hall = {.length_m = 20.0, .width_m = 15.0, .height_m = 6.0, .num_anchors = 6,
            .anchor_height_min_m = 1.0, .anchor_height_max_m = 5.0};
  o.trajectory.height_m = 2.5;
  o.trajectory.vertical_excursion_m = 1.5;
  o.trajectory.hall_duration_s = 200.0;
  o.ranging.sigma_range_m = 0.1;
  o.ranging.outlier_probability = 0.0;
  o.ranging.sigma_position_m = 0.0;
  return o;
}

TEST(Replay, SimulatedWellConditionedRunInitializesEveryAnchorWithinItsBound) {
  const sim::ScenarioOptions options = WellConditionedHall();
  const sim::Scenario scenario = sim::GenerateScenario(options, 4, 0);
  testing::TempDir dir("replay");
  WriteScenarioFiles(scenario, dir.path());  // through the files, as a user would

  const PoseTracks poses = PoseTracks::Load((dir.path() / "poses.csv").string());
  const std::vector<RangeRecord> ranges = LoadRanges((dir.path() / "ranges.csv").string());
  const std::map<int, AnchorTruth> truth = LoadAnchors((dir.path() / "anchors.csv").string());
  estimator::InitializerOptions estimator;
  estimator.filter.consistency.tau_m = 0.3;  // ~2 sigma of a difference of two ranges
  estimator.solver.nls.kernel_scale_m = options.ranging.sigma_range_m;
  const ReplayResult result = Replay(poses, ranges, &truth, estimator);

  EXPECT_EQ(result.ranges_skipped, 0);
  ASSERT_EQ(result.outcomes.size(), 2 * scenario.anchors.size());
  for (const AttemptOutcome& o : result.outcomes) {
    ASSERT_TRUE(o.initialized) << "anchor " << o.anchor_id << " " << o.method;
    if (o.method == kPaperTrigger) {
      EXPECT_LT(o.pdop_estimate, 1.0);
    }
    // The CRLB of (p_A, gamma) on these samples is sigma_d * bias-aware DOP (m, RMS of the 3D
    // error); a 3-dof error exceeds 4x its RMS with probability ~1e-3.
    const double bound_m = 4.0 * options.ranging.sigma_range_m * *o.bias_aware_dop;
    EXPECT_LT(*o.error_m, bound_m) << "anchor " << o.anchor_id << " " << o.method;
  }
}

TEST(Replay, TheOracleTriggerWithoutTruthIsAnInputErrorNamingIt) {
  PoseTracks poses;
  for (int k = 0; k <= 10; ++k) poses.Add(0, k, Eigen::Vector3d(k, 0.5 * k * k, 1.0));
  const std::vector<RangeRecord> ranges = {{1.0, 0, 3, 10.0, 2}};
  estimator::InitializerOptions options;
  options.triggers = {"fixed_window", "pdop_true"};
  try {
    Replay(poses, ranges, nullptr, options);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("anchor 3: trigger 'pdop_true': needs the true anchor position"),
              std::string::npos)
        << e.what();
  }
}

TEST(Replay, RangesOutsideThePoseSpanAreSkippedAndCounted) {
  PoseTracks poses;
  for (int k = 0; k <= 10; ++k) poses.Add(0, 1.0 + k, Eigen::Vector3d(k, 0.5 * k * k, 1.0));
  std::vector<RangeRecord> ranges;
  for (int k = 0; k < 130; ++k) ranges.push_back({0.1 * k, 0, 1, 10.0, k + 2});
  const estimator::InitializerOptions defaults;  // named: GCC 12 warns falsely on a `{}` temporary
  const ReplayResult result = Replay(poses, ranges, nullptr, defaults);
  EXPECT_EQ(result.ranges_skipped, 10 + 19);  // t < 1 s (10 ranges) and t > 11 s (19 ranges)
  EXPECT_EQ(result.first_skipped_line, 2);
  EXPECT_EQ(result.ranges_used, 130 - 29);
}

TEST(Replay, EstimatesCsvHasExactlyTheDocumentedColumns) {
  std::ostringstream out;
  WriteEstimates(out, {});
  EXPECT_EQ(out.str(), "anchor_id,method,initialized,t_init,n_used,pdop_est,pdop_true,x,y,z,bias,err_m\n");
}

}  // namespace
}  // namespace anchorbench::experiments
