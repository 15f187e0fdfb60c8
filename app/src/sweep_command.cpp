#include <iostream>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/engine/commit.hpp"
#include "anchorbench/engine/monte_carlo.hpp"
#include "anchorbench/schema/sweep.hpp"
#include "monte_carlo_command.hpp"

namespace anchorbench::app {

int SweepCommand(const SweepArgs& args, const AppContext& app) {
  const config::ConfigDocument document = config::ReadConfigDocument(args.config);  // read once
  const schema::ExperimentConfig base = config::LoadConfig(document, {}, app.components);
  const std::vector<schema::SweepAxis> axes = schema::SweepAxes(base.sweep, args.axes);
  if (axes.empty()) throw schema::InputError(args.config + ": nothing to sweep: give --set KEY=VALUES or a 'sweep' section");
  for (const schema::SweepAxis& axis : axes) {
    if (args.realizations && axis.key == "realizations") {
      throw schema::InputError("--realizations " + std::to_string(*args.realizations) +
                           " and the sweep axis 'realizations' both set the realizations: give one of them");
    }
  }
  const std::vector<schema::ExperimentConfig> configs =
      engine::SweepPoints(document, {}, axes, args.realizations, app.components);
  const MonteCarloSetup setup = SetUpMonteCarlo(args, base.name);
  const engine::Plan plan(configs);
  const std::unique_ptr<io::ResultFolder> out =
      OpenResultFolder(args, setup, engine::SweepResultBytes(plan, ShardOf(args)));
  schema::ExperimentConfig resolved = base;
  if (args.realizations) resolved.realizations = *args.realizations;
  const engine::ShardInputs inputs{config::ToYaml(resolved), axes};
  if (!args.shard.empty() && engine::RebuildPlan(inputs, app.components).identity() != plan.identity()) {
    throw schema::InputError(args.config + ": this sweep does not rebuild from its config and axes (an axis on "
                         "'realizations' with --realizations?): it cannot be sharded");
  }

  const PlanOutcome points = ComputePlan(args, setup, {plan, "sweep", base.name, app.revision, inputs}, app, *out);
  if (!points.experiments) return 0;  // a shard: its folder is written
  std::vector<std::string> command_line;
  for (const std::string& axis : args.axes) command_line.push_back("--set " + axis);
  const std::string markdown =
      engine::CommitSweep(*out, base.name, axes, plan, *points.experiments,
                  RunInfoOf(args, setup, app, base, points.wall_time_s, command_line));
  engine::RemoveStore(*out);
  if (!args.quiet) std::cout << markdown;
  return 0;
}

}  // namespace anchorbench::app
