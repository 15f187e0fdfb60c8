#include "anchorbench/studies/fit.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "anchorbench/studies/calibration_report.hpp"

namespace anchorbench::studies {
namespace {

namespace fs = std::filesystem;
using report::PaperCell;
using report::PaperColumn;

// Two parameters and two cells whose log-ratios are linear in them: the objective is the quadratic
// ((x - 3)^2 + 4 (y - 0.25)^2) / 2, least at x = 3, y = 0.25.
schema::CalibrationSpec Spec() {
  schema::CalibrationSpec spec;
  spec.parameters = {{"scenario.x", 0.0, 10.0, "test"}, {"scenario.y", -1.0, 1.0, "test"}};
  spec.fit_weight = {1.0, 1.0, 0.0, 0.0, 0.0};
  spec.global = {"GN_DIRECT_L", 40};
  spec.local = {"LN_SBPLX", 60};
  return spec;
}

std::vector<PaperCell> Targets() {
  std::vector<PaperCell> cells(2);
  cells[0].column = PaperColumn::kAvg, cells[0].paper = 1.0, cells[0].scored = true;
  cells[1].column = PaperColumn::kMed, cells[1].paper = 1.0, cells[1].scored = true;
  for (PaperCell& c : cells) c.method = schema::kFixedWindowTrigger;
  return cells;
}

double ValueOf(const std::string& assignment) { return std::stod(assignment.substr(assignment.find('=') + 1)); }

struct FitRun {
  std::string evaluations_csv;
  FitResult result;
  int calls = 0;
  std::vector<std::string> best_values;
};

FitRun Calibrate(const schema::CalibrationSpec& spec, const fs::path& reuse = {}, const fs::path& append = {}) {
  FitRun run;
  EvaluationLog log({"scenario.x", "scenario.y"}, {"1.fixed.avg_m", "1.fixed.med_m"}, 1);
  if (!reuse.empty()) log.Reuse(reuse);
  if (!append.empty()) log.AppendTo(append);
  Fit fit(spec, Targets(), {5.0, 0.0},
          [&](const std::vector<std::string>& overrides) {
            ++run.calls;
            return std::vector<std::optional<double>>{std::exp(ValueOf(overrides[0]) - 3.0),
                                                      std::exp(2.0 * (ValueOf(overrides[1]) - 0.25))};
          },
          &log);
  run.result = fit.Run();
  std::ostringstream csv;
  WriteEvaluationsCsv(csv, log);
  run.evaluations_csv = csv.str();
  run.best_values = log.evaluations()[run.result.best].values;
  return run;
}

TEST(FitTest, FindsTheMinimumFromTheConfiguredPoint) {
  const FitRun run = Calibrate(Spec());
  EXPECT_EQ(run.result.hand, 0u);
  EXPECT_NEAR(std::stod(run.best_values[0]), 3.0, 0.02);
  EXPECT_NEAR(std::stod(run.best_values[1]), 0.25, 0.01);
  EXPECT_EQ(run.result.profile.size(), 8u);  // +-1 and +-2.5 steps of each, none at a bound
}

TEST(FitTest, RepeatsExactly) {
  EXPECT_EQ(Calibrate(Spec()).evaluations_csv, Calibrate(Spec()).evaluations_csv);
}

TEST(FitTest, AKilledRunResumesToTheSameEvaluations) {
  const fs::path dir = fs::temp_directory_path() / "fit_test_resume";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const FitRun whole = Calibrate(Spec(), {}, dir / "whole.csv");
  // The log as a kill after 15 evaluations leaves it: the header and 15 lines, the 16th torn.
  std::ifstream in(dir / "whole.csv");
  std::ofstream killed(dir / "killed.csv");
  std::string line;
  for (int i = 0; i < 17 && std::getline(in, line); ++i) killed << (i < 16 ? line + "\n" : line.substr(0, 20));
  killed.close();
  const FitRun resumed = Calibrate(Spec(), dir / "killed.csv", dir / "killed.csv");
  EXPECT_EQ(resumed.evaluations_csv, whole.evaluations_csv);
  EXPECT_EQ(resumed.calls + 15, whole.calls);
  fs::remove_all(dir);
}

TEST(FitTest, ValuesAreEvaluatedOnAGridAndPrintedAsEvaluated) {
  const schema::FreeParameter p{"scenario.x", 6.0, 24.0, "test"};
  EXPECT_EQ(Fit::ValueText(p, 0.0), "6");
  EXPECT_EQ(Fit::ValueText(p, 1.0), "24");
  EXPECT_EQ(Fit::ValueText(p, 0.12344), "8.2212");  // u on the 1e-4 grid
  EXPECT_EQ(Fit::ValueText(p, 1.5), "24");           // clamped to the box
}

}  // namespace
}  // namespace anchorbench::studies
