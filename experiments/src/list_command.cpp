#include <iomanip>
#include <iostream>

#include "anchorbench/experiments/anchor_bank.hpp"
#include "anchorbench/experiments/commands.hpp"

namespace anchorbench::experiments {

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
