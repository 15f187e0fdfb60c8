#include "anchorbench/estimator/triggers.hpp"

#include <cmath>

#include "anchorbench/estimator/pdop.hpp"

namespace anchorbench::estimator {

bool TriggerOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* message) {
    if (why) *why = message;
    return false;
  };
  if (!(pdop_threshold > 0.0)) return fail("pdop_threshold must be > 0");
  if (sample_count < 1) return fail("sample_count must be >= 1");
  if (!(timeout_s >= 0.0) || !std::isfinite(timeout_s)) return fail("timeout_s must be >= 0");
  if (evaluate_every < 1) return fail("evaluate_every must be >= 1");
  return true;
}

bool EstimatePdopTrigger::Fire(const TriggerInput& in) {
  const std::size_t n = in.n_accepted;
  if (!in.eligible || (evaluated_at_ != 0 && n < evaluated_at_ + every_)) return false;
  evaluated_at_ = n;
  const SolveResult estimate = solver_->Solve(in.p_world_tag, in.range_m);
  return Succeeded(estimate.status) && GeometryPdop(in.p_world_tag, in.range_m, estimate.p_world_anchor) < threshold_;
}

}  // namespace anchorbench::estimator
