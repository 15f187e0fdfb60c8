#include <iostream>

#include "anchorbench/experiments/commands.hpp"
#include "anchorbench/experiments/config.hpp"
#include "anchorbench/experiments/scenario_files.hpp"

namespace anchorbench::experiments {

int SimulateCommand(const SimulateArgs& args) {
  ExperimentConfig config = LoadConfig(args.config, args.overrides);
  if (args.seed) config.seed = *args.seed;
  const sim::Scenario scenario = sim::GenerateScenario(config.scenario, config.seed, args.realization);
  WriteScenarioFiles(scenario, args.out);
  int outliers = 0;
  for (const sim::SimRange& r : scenario.ranges) outliers += r.is_outlier;
  std::cout << "simulate: " << scenario.t_s.size() << " poses, " << scenario.ranges.size() << " ranges (" << outliers
            << " outliers), " << scenario.anchors.size() << " anchors -> " << args.out << '\n';
  return 0;
}

}  // namespace anchorbench::experiments
