#include <iomanip>
#include <iostream>

#include "anchorbench/experiments/anchor_bank.hpp"
#include "anchorbench/experiments/commands.hpp"

namespace anchorbench::experiments {
namespace {

template <typename Registry>
void Print(const char* heading, const Registry& registry) {
  std::cout << heading << '\n';
  for (const auto& [name, description] : registry.List()) {
    std::cout << "  " << std::left << std::setw(20) << name << description << '\n';
  }
}

}  // namespace

int ListCommand() {
  const estimator::Components& parts = BuiltinComponents();
  Print("solvers (estimator.solver):", parts.solvers);
  Print("filters (estimator.filter.kind):", parts.filters);
  Print("triggers (estimator.triggers, run side by side on the same data):", parts.triggers);
  return 0;
}

}  // namespace anchorbench::experiments
