#include <iostream>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/engine/commit.hpp"
#include "anchorbench/engine/monte_carlo.hpp"
#include "monte_carlo_command.hpp"

namespace anchorbench::app {
int RunCommand(const RunArgs& args, const AppContext& app) {
  schema::ExperimentConfig config = config::LoadConfig(args.config, args.overrides, app.components);
  if (args.seed) config.seed = *args.seed;
  if (args.realizations) config.realizations = *args.realizations;
  engine::CheckExperiment(config, app.components);
  const MonteCarloSetup setup = SetUpMonteCarlo(args, config.name);
  const engine::Plan plan({config});
  const std::unique_ptr<io::ResultFolder> out = OpenResultFolder(args, setup, engine::RunResultBytes(plan, ShardOf(args)));

  const PlanOutcome run = ComputePlan(args, setup, {plan, "run", config.name, app.revision, {config::ToYaml(config), {}}}, app, *out);
  if (!run.experiments) return 0;  // a shard: its folder is written
  std::vector<std::string> command_line = CommandLine("", args.overrides);
  if (args.seed) command_line.insert(command_line.begin(), "--seed " + std::to_string(*args.seed));
  const std::string markdown =
      engine::CommitRun(*out, config, run.experiments->front(), RunInfoOf(args, setup, app, config, run.wall_time_s, command_line));
  engine::RemoveStore(*out);
  if (!args.quiet) std::cout << markdown;
  return 0;
}

}  // namespace anchorbench::app
