#include <iomanip>
#include <iostream>

#include "anchorbench/experiments/anchor_bank.hpp"
#include "anchorbench/experiments/commands.hpp"
#include "anchorbench/experiments/config.hpp"
#include "anchorbench/experiments/hanyang.hpp"
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

int ConvertHanyangCommand(const ConvertHanyangArgs& args) {
  const HanyangSummary s = ConvertHanyangCase(args.case_folder, args.out);
  std::cout << "convert-hanyang: " << s.poses << " poses, " << s.ranges << " ranges, " << s.anchors << " anchors -> "
            << args.out;
  if (s.dropped_poses > 0) std::cout << " (" << s.dropped_poses << " trajectory rows with non-increasing time dropped)";
  std::cout << '\n';
  return 0;
}

int ListCommand() {
  std::cout << "solvers (estimator.solver):\n";
  for (const auto& [name, description] : BuiltinSolvers().List()) {
    std::cout << "  " << std::left << std::setw(20) << name << description << '\n';
  }
  std::cout << "filters (estimator.filter):\n"
            << "  " << std::setw(20) << "consistency" << "the triangle check of Sec. III-B (filter.enabled: true)\n"
            << "  " << std::setw(20) << "none" << "every range accepted (filter.enabled: false)\n"
            << "triggers:\n"
            << "  " << std::setw(20) << "pdop_closest_point" << "gated: closest-point PDOP < trigger.pdop_threshold (Eq. (4))\n"
            << "  " << std::setw(20) << "fixed_window" << "all of an anchor's data at the end of the run\n"
            << "  " << std::setw(20) << "pdop_ls, pdop_nls, pdop_true" << " compared side by side by anchorbench pdop-study\n";
  return 0;
}

}  // namespace anchorbench::experiments
