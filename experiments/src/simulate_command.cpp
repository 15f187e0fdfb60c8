#include <iostream>

#include "anchorbench/experiments/commands.hpp"
#include "anchorbench/experiments/config.hpp"
#include "anchorbench/experiments/scenario_files.hpp"

namespace anchorbench::experiments {

Action AddSimulateCommand(CLI::App& app) {
  struct Args {
    std::string config;
    std::string out;
    std::optional<std::uint64_t> seed;
    std::uint64_t realization = 0;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("simulate", "Simulate one realization and write poses.csv, ranges.csv, anchors.csv");
  cmd->add_option("config", args->config, "Experiment config (YAML)")->required();
  cmd->add_option("--out", args->out, "Output folder (created if needed)")->required();
  cmd->add_option("--seed", args->seed, "Override the config's seed");
  cmd->add_option("--realization", args->realization, "Realization index (default 0)");
  return [args]() {
    ExperimentConfig config = LoadConfig(args->config);
    if (args->seed) config.seed = *args->seed;
    const sim::Scenario scenario = sim::GenerateScenario(config.scenario, config.seed, args->realization);
    WriteScenarioFiles(scenario, args->out);
    int outliers = 0;
    for (const sim::SimRange& r : scenario.ranges) outliers += r.is_outlier;
    std::cout << "simulate: " << scenario.t_s.size() << " poses, " << scenario.ranges.size() << " ranges ("
              << outliers << " outliers), " << scenario.anchors.size() << " anchors -> " << args->out << '\n';
    return 0;
  };
}

}  // namespace anchorbench::experiments
