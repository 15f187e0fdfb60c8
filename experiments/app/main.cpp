// anchorbench: Monte Carlo simulation and benchmarking of online UWB anchor initialization.
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "anchorbench/experiments/commands.hpp"
#include "anchorbench/experiments/input_error.hpp"

int main(int argc, char** argv) {
  namespace ex = anchorbench::experiments;
  CLI::App app{"anchorbench: online initialization of unknown UWB anchors (Delama et al., IROS 2025)"};
  app.require_subcommand(1);
  const std::vector<std::pair<std::string, ex::Action>> actions = {
      {"simulate", ex::AddSimulateCommand(app)},
      {"replay", ex::AddReplayCommand(app)},
      {"run", ex::AddRunCommand(app)},
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    for (const auto& [name, action] : actions) {
      if (app.got_subcommand(name)) return action();
    }
  } catch (const ex::InputError& e) {
    std::cerr << "anchorbench: error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "anchorbench: internal error: " << e.what() << '\n';
    return 3;
  }
  return 1;
}
