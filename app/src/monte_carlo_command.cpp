#include "monte_carlo_command.hpp"

#include "anchorbench/config/load_config.hpp"
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
