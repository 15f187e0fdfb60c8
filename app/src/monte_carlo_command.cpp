#include "monte_carlo_command.hpp"

#include <sstream>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/report/summary.hpp"
#include "anchorbench/runner/monte_carlo.hpp"

namespace anchorbench::app {

MonteCarloSetup SetUpMonteCarlo(const MonteCarloArgs& args, const std::string& config_name) {
  MonteCarloSetup setup;
  setup.threads = runner::ResolveThreads(args.threads);
  setup.out = io::ResultFolderPath(args.out, config_name);
  return setup;
}

std::unique_ptr<io::ResultFolder> OpenResultFolder(const MonteCarloArgs& args, const MonteCarloSetup& setup,
                                                  std::uintmax_t expected_bytes) {
  io::ResultFolder::Options options;
  options.overwrite = args.overwrite;
  options.expected_bytes = expected_bytes;
  options.inputs = {args.config};
  return std::make_unique<io::ResultFolder>(setup.out, options);
}

work::ChunkStore::Mode StoreMode(const MonteCarloArgs& args) {
  if (args.resume) return work::ChunkStore::Mode::kResume;
  return args.overwrite ? work::ChunkStore::Mode::kOverwrite : work::ChunkStore::Mode::kFresh;
}

std::string WriteRunTables(io::ResultFolder& out, const std::vector<runner::Attempt>& attempts,
                           const std::vector<runner::RowConfig>& rows, const runner::ExperimentConfig& config) {
  const std::vector<report::MethodSummary> summaries =
      report::Summarize(attempts, rows, config.realizations, config.bootstrap_resamples, config.seed);
  out.Write("summary.csv", [&](std::ostream& file) { report::WriteSummaryCsv(file, summaries, rows); });
  std::ostringstream markdown;
  report::WriteSummaryMarkdown(markdown, summaries, rows, config);
  out.Write("summary.md", markdown.str());
  out.Write("timing.csv", [&](std::ostream& file) { report::WriteTimingCsv(file, summaries, rows); });
  return markdown.str();
}

report::RunInfo RunInfoOf(const MonteCarloArgs& args, const MonteCarloSetup& setup, const AppContext& app,
                          const runner::ExperimentConfig& config, double wall_time_s,
                          std::vector<std::string> more_command_line) {
  report::RunInfo info;
  info.config_path = args.config;
  info.revision = app.revision;
  info.threads = setup.threads;
  info.wall_time_s = wall_time_s;
  if (args.realizations) info.command_line.push_back("--realizations " + std::to_string(*args.realizations));
  for (std::string& item : more_command_line) info.command_line.push_back(std::move(item));
  info.resolved_config_json = config::ToJson(config);
  return info;
}

}  // namespace anchorbench::app
