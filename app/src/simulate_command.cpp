#include <iostream>

#include "anchorbench/config/config_yaml.hpp"
#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/scenario_files.hpp"
#include "commands.hpp"

namespace anchorbench::app {

int SimulateCommand(const SimulateArgs& args, const AppContext& app) {
  schema::ExperimentConfig config = config::LoadConfig(args.config, args.overrides, app.components);
  if (args.seed) config.seed = *args.seed;
  const sim::Scenario scenario = sim::GenerateScenario(config.scenario, config.seed, args.realization);
  std::vector<std::filesystem::path> inputs;  // the config and every base it chains to
  for (const std::string& file : config::ConfigFiles(args.config)) inputs.emplace_back(file);
  io::WriteRecordingFolder(args.out, io::RecordingOf(scenario), args.overwrite, inputs);
  int outliers = 0;
  for (const sim::SimRange& r : scenario.ranges) outliers += r.is_outlier;
  std::cout << "simulate: " << scenario.t_s.size() << " poses, " << scenario.ranges.size() << " ranges (" << outliers
            << " outliers), " << scenario.anchors.size() << " anchors -> " << args.out << '\n';
  return 0;
}

}  // namespace anchorbench::app
