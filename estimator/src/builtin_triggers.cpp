#include <cmath>
#include <stdexcept>

#include "anchorbench/estimator/pdop.hpp"
#include "anchorbench/estimator/trigger_registry.hpp"

namespace anchorbench::estimator {

bool TriggerOptions::IsValid(std::string* why) const {
  const bool ok = pdop_threshold > 0.0 && !std::isnan(pdop_threshold) && sample_count >= 1 && timeout_s >= 0.0 &&
                  std::isfinite(timeout_s) && evaluate_every >= 1;
  if (!ok && why) *why = "trigger needs pdop_threshold > 0, sample_count >= 1, timeout_s >= 0, evaluate_every >= 1";
  return ok;
}

namespace {

// Sec. IV-B's alternatives: Eq. (2)-(3) at the current estimate of a solver (LS, or the NLS the
// anchor is initialized with), re-solved every `every` accepted samples.
class EstimatePdopTrigger : public InitTrigger {
 public:
  EstimatePdopTrigger(std::shared_ptr<const Solver> solver, double threshold, int every)
      : solver_(std::move(solver)), threshold_(threshold), every_(static_cast<std::size_t>(every)) {}

  bool Fire(const TriggerInput& in) override {
    const std::size_t n = in.range_m.size();
    if (!in.eligible || (evaluated_at_ != 0 && n < evaluated_at_ + every_)) return false;
    evaluated_at_ = n;
    const SolveResult estimate = solver_->Solve(in.p_world_tag, in.range_m);
    return Succeeded(estimate.status) && GeometryPdop(in.p_world_tag, in.range_m, estimate.p_world_anchor) < threshold_;
  }

 private:
  std::shared_ptr<const Solver> solver_;
  double threshold_;
  std::size_t every_;
  std::size_t evaluated_at_ = 0;  // sample count of the last evaluation (0: none yet)
};

// The oracle of Sec. IV-B: the true PDOP, Eq. (3) at the true anchor, O(1) per sample.
class TruePdopTrigger : public InitTrigger {
 public:
  TruePdopTrigger(const Eigen::Vector3d& p_world_anchor, double threshold)
      : geometry_(p_world_anchor), threshold_(threshold) {}
  bool Fire(const TriggerInput& in) override {
    geometry_.Add(in.p_world_tag.back());
    return in.eligible && geometry_.Pdop() < threshold_;
  }

 private:
  TrueGeometry geometry_;
  double threshold_;
};

// The baseline of Sec. IV-A: never online; the initializer solves on everything at the end.
class FixedWindowTrigger : public InitTrigger {
 public:
  bool Fire(const TriggerInput&) override { return false; }
  bool online() const override { return false; }
};

class SampleCountTrigger : public InitTrigger {
 public:
  explicit SampleCountTrigger(int count) : count_(static_cast<std::size_t>(count)) {}
  bool Fire(const TriggerInput& in) override { return in.eligible && in.range_m.size() >= count_; }

 private:
  std::size_t count_;
};

class TimeoutTrigger : public InitTrigger {
 public:
  explicit TimeoutTrigger(double timeout_s) : timeout_s_(timeout_s) {}
  bool Fire(const TriggerInput& in) override { return in.eligible && in.t_s - in.t_first_s >= timeout_s_; }

 private:
  double timeout_s_;
};

}  // namespace

void RegisterBuiltinTriggers(TriggerRegistry& registry) {
  using Context = TriggerContext;
  registry.Register("pdop_closest_point",
                    "closest-point PDOP < trigger.pdop_threshold, Eq. (4), O(1): the paper's trigger",
                    [](const std::string&, const Context& c) {
                      return std::make_unique<ClosestPointPdopTrigger>(c.options.pdop_threshold);
                    });
  registry.Register("pdop_ls", "PDOP at the LS estimate < trigger.pdop_threshold (every trigger.evaluate_every samples)",
                    [](const std::string&, const Context& c) {
                      return std::make_unique<EstimatePdopTrigger>(std::make_shared<DoubleDifferenceLsSolver>(c.ls),
                                                                   c.options.pdop_threshold, c.options.evaluate_every);
                    });
  registry.Register("pdop_nls",
                    "PDOP at the solver's estimate < trigger.pdop_threshold (every trigger.evaluate_every samples)",
                    [](const std::string&, const Context& c) {
                      if (!c.solver) throw std::invalid_argument("needs the anchor's solver");
                      return std::make_unique<EstimatePdopTrigger>(c.solver, c.options.pdop_threshold,
                                                                   c.options.evaluate_every);
                    });
  registry.Register("pdop_true", "oracle: true PDOP (at the true anchor) < trigger.pdop_threshold; needs the truth",
                    [](const std::string&, const Context& c) {
                      if (!c.p_world_anchor_true) {
                        throw std::invalid_argument(
                            "needs the true anchor position (simulation, or anchors.csv in replay)");
                      }
                      return std::make_unique<TruePdopTrigger>(*c.p_world_anchor_true, c.options.pdop_threshold);
                    });
  registry.Register("fixed_window", "the baseline: one solve on all of an anchor's data at the end of the run",
                    [](const std::string&, const Context&) { return std::make_unique<FixedWindowTrigger>(); });
  registry.Register("sample_count", "after trigger.sample_count accepted samples",
                    [](const std::string&, const Context& c) {
                      return std::make_unique<SampleCountTrigger>(c.options.sample_count);
                    });
  registry.Register("timeout", "trigger.timeout_s after the anchor's first accepted sample",
                    [](const std::string&, const Context& c) {
                      return std::make_unique<TimeoutTrigger>(c.options.timeout_s);
                    });
}

}  // namespace anchorbench::estimator
