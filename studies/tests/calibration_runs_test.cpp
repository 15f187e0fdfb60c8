#include "anchorbench/studies/calibration_runs.hpp"

#include <gtest/gtest.h>

#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/testing/components.hpp"
#include "anchorbench/testing/temp_dir.hpp"

namespace anchorbench::studies {
namespace {

using engine::LocalExecutor;

using report::PaperCell;
using report::PaperColumn;
using testing::AllComponents;

// Two rows with the paper's cells; width 10 m.
constexpr const char* kExperiment = R"(seed: 5
realizations: 6
bootstrap_resamples: 50
scenario:
  tunnel: {length_m: 60, width_m: 10, num_anchors: 4}
  trajectory: {kind: random, rate_hz: 5}
  ranging: {sigma_range_m: 0.1, outlier_probability: 0.02}
rows:
  - name: "1"
    paper:
      fixed: {avg_m: 0.2, med_m: 0.05, init: 24, gt1m: 1, ratio_pct: 5}
      gated: {avg_m: 0.1, med_m: 0.05, init: 8, gt1m: 0, ratio_pct: 0}
  - name: "2"
    scenario: {ranging: {sigma_range_m: 0.3}}
    paper:
      fixed: {avg_m: 0.4, med_m: 0.1, init: 24, gt1m: 2, ratio_pct: 10}
      gated: {avg_m: 0.2, med_m: 0.1, init: 6, gt1m: 0, ratio_pct: 0}
)";

schema::CalibrationSpec Spec(const testing::TempDir& dir, double min_width_m = 6.0) {
  schema::CalibrationSpec spec;
  spec.path = (dir.path() / "cal.yaml").string();
  spec.experiment_path = dir.Write("tiny.yaml", kExperiment);
  spec.parameters = {{"scenario.tunnel.width_m", min_width_m, 20.0, "not stated"}};
  spec.seed = 11;
  spec.realizations = 3;
  spec.verify_seeds = {2, 3};
  return spec;
}

std::optional<double> Cell(const std::vector<PaperCell>& cells, PaperColumn column, int row = 0) {
  for (const PaperCell& cell : cells) {
    if (cell.column == column && cell.row == row && cell.method == schema::kPaperTrigger) return cell.ours;
  }
  return std::nullopt;
}

TEST(CalibrationRuns, ReadTheExperimentOnceAndLayEachAssignmentOverIt) {
  const testing::TempDir dir("calibration_runs_once");
  const schema::CalibrationSpec spec = Spec(dir);
  LocalExecutor executor(AllComponents());
  const CalibrationRuns runs(spec, AllComponents(), executor, 2);
  ASSERT_EQ(runs.hand_values(), std::vector<double>{10.0});
  const std::vector<PaperCell> before = runs.Cells({"scenario.tunnel.width_m=16"}, 11, 3, false);
  std::filesystem::remove(spec.experiment_path);  // no evaluation reads the file again
  EXPECT_EQ(runs.Experiment({"scenario.tunnel.width_m=16"}).scenario.tunnel.width_m, 16.0);
  const std::vector<PaperCell> after = runs.Cells({"scenario.tunnel.width_m=16"}, 11, 3, false);
  ASSERT_EQ(before.size(), after.size());
  for (std::size_t c = 0; c < before.size(); ++c) EXPECT_EQ(before[c].ours, after[c].ours) << c;
  EXPECT_EQ(runs.experiment().scenario.tunnel.width_m, 10.0);  // the document is left as read
}

TEST(CalibrationRuns, TheEvaluatorScalesCountsToTheExperimentsSize) {
  const testing::TempDir dir("calibration_runs_scale");
  const schema::CalibrationSpec spec = Spec(dir);
  LocalExecutor executor(AllComponents());
  const CalibrationRuns runs(spec, AllComponents(), executor, 2);
  const std::vector<PaperCell> cells = runs.Cells({}, spec.seed, spec.realizations, false);
  const std::vector<std::optional<double>> ours = runs.FitEvaluator()({});
  ASSERT_EQ(ours.size(), cells.size());
  bool scaled_a_count = false;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const bool count = cells[c].column == PaperColumn::kInit || cells[c].column == PaperColumn::kGt1m;
    ASSERT_EQ(ours[c].has_value(), cells[c].ours.has_value());
    if (!ours[c]) continue;
    EXPECT_DOUBLE_EQ(*ours[c], *cells[c].ours * (count ? 6.0 / 3.0 : 1.0)) << c;
    scaled_a_count |= count && *cells[c].ours > 0;
  }
  EXPECT_TRUE(scaled_a_count);
  EXPECT_TRUE(Cell(cells, PaperColumn::kInit).has_value());
}

TEST(CalibrationRuns, TheContextFollowsTheFitsSeedAndSize) {
  const testing::TempDir dir("calibration_runs_context");
  schema::CalibrationSpec spec = Spec(dir);
  LocalExecutor executor(AllComponents());
  const std::uint64_t context = CalibrationRuns(spec, AllComponents(), executor, 1).Context();
  spec.seed = 12;
  EXPECT_NE(CalibrationRuns(spec, AllComponents(), executor, 1).Context(), context);
}

TEST(CalibrationRuns, RefuseABoundOutsideTheExperimentOrOneItCannotRun) {
  const testing::TempDir dir("calibration_runs_bounds");
  LocalExecutor executor(AllComponents());
  try {
    CalibrationRuns(Spec(dir, 12.0), AllComponents(), executor, 1);
    ADD_FAILURE() << "a configured value outside the bounds was accepted";
  } catch (const schema::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the experiment's value 10 lies outside [min, max]"), std::string::npos)
        << e.what();
  }
  try {
    CalibrationRuns(Spec(dir, -1.0), AllComponents(), executor, 1);
    ADD_FAILURE() << "a bound the experiment refuses was accepted";
  } catch (const schema::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("(scenario.tunnel.width_m) at its min"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace anchorbench::studies
