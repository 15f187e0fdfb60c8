#include <iostream>
#include <sstream>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/io/input_error.hpp"
#include "anchorbench/report/summary.hpp"
#include "anchorbench/report/sweep_report.hpp"
#include "anchorbench/runner/monte_carlo.hpp"
#include "anchorbench/runner/sweep.hpp"
#include "anchorbench/work/run_plan.hpp"
#include "monte_carlo_command.hpp"

namespace anchorbench::app {
namespace {

// Every grid point parsed and validated before the first trial runs.
std::vector<runner::ExperimentConfig> PointConfigs(const SweepArgs& args, const std::vector<runner::SweepPoint>& grid,
                                                   const AppContext& app) {
  std::vector<runner::ExperimentConfig> configs;
  for (const runner::SweepPoint& point : grid) {
    runner::ExperimentConfig config = config::LoadConfig(args.config, point.overrides, app.parts);
    if (args.realizations) config.realizations = *args.realizations;
    runner::CheckWork(config);
    runner::CheckRows(runner::RowsOf(config), app.parts);
    configs.push_back(std::move(config));
  }
  return configs;
}

}  // namespace

int SweepCommand(const SweepArgs& args, const AppContext& app) {
  const runner::ExperimentConfig base = config::LoadConfig(args.config, {}, app.parts);
  const std::vector<runner::SweepAxis> axes = runner::SweepAxes(base.sweep, args.axes);
  if (axes.empty()) throw io::InputError(args.config + ": nothing to sweep: give --set KEY=VALUES or a 'sweep' section");
  const std::vector<runner::SweepPoint> grid = runner::SweepGrid(axes);
  const std::vector<runner::ExperimentConfig> configs = PointConfigs(args, grid, app);
  const MonteCarloSetup setup = SetUpMonteCarlo(args, base.name);
  // Per point, row and trigger a line of ~200 bytes in each of three files.
  std::uintmax_t lines = 0;
  for (const runner::ExperimentConfig& config : configs) {
    for (const runner::RowConfig& row : runner::RowsOf(config)) lines += row.estimator.triggers.size();
  }
  const std::unique_ptr<io::ResultFolder> out = OpenResultFolder(args, setup, 600 * lines + (1 << 16));
  const work::Plan plan(configs);
  work::ChunkStore store(setup.out, plan, StoreMode(args));

  Progress progress("sweep " + base.name, args.quiet);
  std::vector<work::ExperimentAttempts> points = work::RunPlan(
      plan, app.executor, {setup.threads, &store, [&](long long done, long long total) { progress.Update(done, total); }});
  std::vector<report::SweepPointResult> results;
  for (std::size_t p = 0; p < configs.size(); ++p) {
    const runner::ExperimentConfig& config = configs[p];
    report::SweepPointResult result{grid[p], plan.rows(static_cast<int>(p)), {}};
    result.summaries =
        report::Summarize(points[p].attempts, result.rows, config.realizations, config.bootstrap_resamples, config.seed);
    results.push_back(std::move(result));
  }
  const double wall_time_s = progress.elapsed_s();
  progress.Finish(plan.units());

  out->Write("sweep.csv", [&](std::ostream& file) { report::WriteSweepCsv(file, axes, results); });
  out->Write("timing.csv", [&](std::ostream& file) { report::WriteSweepTiming(file, axes, results); });
  std::ostringstream md;
  report::WriteSweepMarkdown(md, base.name, configs.front().realizations, configs.front().seed, axes, results);
  out->Write("sweep.md", md.str());
  std::vector<std::string> command_line;
  for (const std::string& axis : args.axes) command_line.push_back("--set " + axis);
  report::RunInfo info = RunInfoOf(args, setup, app, base, wall_time_s, command_line);
  info.sweep_axes = runner::DescribeAxes(axes);
  out->Write("manifest.json", report::ManifestJson(configs.front(), info));
  out->Commit();
  store.Remove();
  if (!args.quiet) std::cout << md.str();
  return 0;
}

}  // namespace anchorbench::app
