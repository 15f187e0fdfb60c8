#include <iostream>
#include <sstream>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/atomic_file.hpp"
#include "anchorbench/report/run_outputs.hpp"
#include "anchorbench/report/summary.hpp"
#include "anchorbench/runner/monte_carlo.hpp"
#include "monte_carlo_command.hpp"

namespace anchorbench::app {

int RunCommand(const RunArgs& args, const AppContext& app) {
  runner::ExperimentConfig config = config::LoadConfig(args.config, args.overrides, app.parts);
  if (args.seed) config.seed = *args.seed;
  if (args.realizations) config.realizations = *args.realizations;
  const std::vector<runner::RowConfig> rows = runner::RowsOf(config);
  runner::CheckRows(rows, app.parts);
  const MonteCarloSetup setup = SetUpMonteCarlo(args, config.name);

  Progress progress("run " + config.name, args.quiet);
  const std::vector<runner::Attempt> attempts = runner::RunMonteCarlo(
      config, app.parts, {setup.threads, [&](int done, int total) { progress.Update(done, total); }});
  const double wall_time_s = progress.elapsed_s();
  progress.Finish(static_cast<int>(rows.size()) * config.realizations);
  const std::vector<report::MethodSummary> summaries =
      report::Summarize(attempts, rows, config.realizations, config.bootstrap_resamples, config.seed);

  std::vector<std::string> command_line;
  if (args.seed) command_line.push_back("--seed " + std::to_string(*args.seed));
  for (const std::string& assignment : args.overrides) command_line.push_back("--set " + assignment);
  // Build every file first, then commit them together: an error leaves the old results intact.
  io::AtomicFile attempts_file(setup.out / "attempts.csv");
  report::WriteAttempts(attempts_file.stream(), attempts, rows);
  io::AtomicFile summary_csv(setup.out / "summary.csv");
  report::WriteSummaryCsv(summary_csv.stream(), summaries, rows);
  std::ostringstream markdown;
  report::WriteSummaryMarkdown(markdown, summaries, rows, config);
  io::AtomicFile summary_md(setup.out / "summary.md");
  summary_md.stream() << markdown.str();
  io::AtomicFile timing(setup.out / "timing.csv");
  report::WriteTimingCsv(timing.stream(), summaries, rows);
  io::AtomicFile manifest(setup.out / "manifest.json");
  manifest.stream() << report::ManifestJson(config, RunInfoOf(args, setup, app, config, wall_time_s, command_line));
  for (io::AtomicFile* file : {&attempts_file, &summary_csv, &summary_md, &timing, &manifest}) file->Commit();
  if (!args.quiet) std::cout << markdown.str();
  return 0;
}

}  // namespace anchorbench::app
