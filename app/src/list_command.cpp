#include <iomanip>
#include <iostream>

#include "commands.hpp"

namespace anchorbench::app {
namespace {

// `section`: where a part's own options go in a config ("estimator", "scenario").
template <typename Registry>
void Print(const char* heading, const Registry& registry, const char* section = "estimator") {
  std::cout << heading << '\n';
  for (const auto& [name, description] : registry.List()) {
    std::cout << "  " << std::left << std::setw(20) << name << description << '\n';
    // A part's own options: <section>.<name>.<key>, with its default.
    if (const registry::PartOptions* options = registry.OptionsOf(name)) {
      for (const registry::OptionSpec& spec : options->specs) {
        std::cout << "    " << section << '.' << name << '.' << spec.key << " (default " << spec.default_value << "): "
                  << spec.description << '\n';
      }
    }
  }
}

}  // namespace

int ListCommand(const AppContext& app) {
  Print("solvers (estimator.solver):", app.components.solvers);
  Print("filters (estimator.filter.kind):", app.components.filters);
  Print("triggers (estimator.triggers, run side by side on the same data):", app.components.triggers);
  Print("environments (scenario.environment): tunnel, hall (their keys: docs/config.md), and",
        app.components.environments, "scenario");
  return 0;
}

}  // namespace anchorbench::app
