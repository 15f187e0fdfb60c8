#include "anchorbench/estimator/solve_result.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace anchorbench::estimator {
namespace {

// The samples at which `value`, growing in proportion to them from `samples`, reaches `needed`.
double SamplesToReach(double samples, double value, double needed) {
  if (!(needed > 0.0) || value == std::numeric_limits<double>::infinity()) return 0.0;  // passed already
  if (!(value > 0.0)) return std::numeric_limits<double>::infinity();                    // not growing (or NaN)
  return samples * needed / value;
}

}  // namespace

double FitComparison::SamplesNeeded() const {
  // Both tests at the rates they have shown: the evidence at its own (it is what the test judges;
  // at zero or below, the mirror fits as well as the estimate, or the model error could explain
  // what it fits worse by, both in proportion to the samples: more of the same will not tell),
  // the separation at the geometry's.
  const auto n = static_cast<double>(samples);
  return std::max(SamplesToReach(n, evidence, evidence_needed), SamplesToReach(n, separation, separation_needed));
}

}  // namespace anchorbench::estimator
