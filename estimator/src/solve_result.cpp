#include "anchorbench/estimator/solve_result.hpp"

namespace anchorbench::estimator {

std::string_view ToString(SolveStatus status) {
  switch (status) {
    case SolveStatus::kConverged: return "converged";
    case SolveStatus::kMaxIterations: return "max_iterations";
    case SolveStatus::kNoConvergence: return "no_convergence";
    case SolveStatus::kTooFewSamples: return "too_few_samples";
    case SolveStatus::kDegenerateGeometry: return "degenerate_geometry";
    case SolveStatus::kNumericalFailure: return "numerical_failure";
    case SolveStatus::kHeightUnobservable: return "height_unobservable";
    case SolveStatus::kBudgetSpent: return "budget_spent";
  }
  return "unknown";
}

}  // namespace anchorbench::estimator
