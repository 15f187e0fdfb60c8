#pragma once

#include <CLI/CLI.hpp>

namespace anchorbench::experiments {

// Each subcommand registers its options on `app` and returns the action to run once parsed.
// Actions return the process exit code; InputError propagates to main(), which reports it.
using Action = std::function<int()>;

Action AddSimulateCommand(CLI::App& app);
Action AddReplayCommand(CLI::App& app);
Action AddRunCommand(CLI::App& app);

}  // namespace anchorbench::experiments
