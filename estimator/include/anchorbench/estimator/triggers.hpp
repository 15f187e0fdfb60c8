#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "anchorbench/estimator/init_trigger.hpp"
#include "anchorbench/estimator/solver.hpp"

namespace anchorbench::estimator {

// The settings of the built-in triggers (the config's estimator.trigger section).
struct TriggerOptions {
  double pdop_threshold = 1.0;  // PDOP triggers: fire once the PDOP is below this (Sec. IV-A uses 1)
  int sample_count = 300;       // SampleCountTrigger: fire at this many accepted samples
  double timeout_s = 30.0;      // TimeoutTrigger: fire this long after the anchor's first accepted sample
  // EstimatePdopTrigger: solve for the estimate every this many accepted samples. Each solve is
  // O(N), so solving at every sample would make an anchor O(N^2).
  int evaluate_every = 10;

  bool IsValid(std::string* why) const;
};

// The paper's trigger (Sec. III-C): the closest-point PDOP of Eq. (4) below a threshold, O(1).
class ClosestPointPdopTrigger : public InitTrigger {
 public:
  explicit ClosestPointPdopTrigger(double threshold) : threshold_(threshold) {}
  bool Fire(const TriggerInput& in) override { return in.eligible && in.pdop < threshold_; }

 private:
  double threshold_;
};

// Sec. IV-B's alternatives: Eqs. (2)-(3) at the current estimate of a solver (LS, or the NLS the
// anchor is initialized with), re-solved every `every` accepted samples.
class EstimatePdopTrigger : public InitTrigger {
 public:
  EstimatePdopTrigger(std::shared_ptr<const Solver> solver, double threshold, int every)
      : solver_(std::move(solver)), threshold_(threshold), every_(static_cast<std::size_t>(every)) {}
  bool Fire(const TriggerInput& in) override;

 private:
  std::shared_ptr<const Solver> solver_;
  double threshold_;
  std::size_t every_;
  std::size_t evaluated_at_ = 0;  // sample count of the last evaluation (0: none yet)
};

// The baseline of Sec. IV-A: never online; the initializer solves on everything at the end.
class FixedWindowTrigger : public InitTrigger {
 public:
  bool Fire(const TriggerInput&) override { return false; }
  bool online() const override { return false; }
};

// A budget of data, blind to geometry.
class SampleCountTrigger : public InitTrigger {
 public:
  explicit SampleCountTrigger(int count) : count_(static_cast<std::size_t>(count)) {}
  bool Fire(const TriggerInput& in) override { return in.eligible && in.n_accepted >= count_; }

 private:
  std::size_t count_;
};

// A budget of time since the anchor's first accepted sample, blind to geometry.
class TimeoutTrigger : public InitTrigger {
 public:
  explicit TimeoutTrigger(double timeout_s) : timeout_s_(timeout_s) {}
  bool Fire(const TriggerInput& in) override { return in.eligible && in.t_s - in.t_first_s >= timeout_s_; }

 private:
  double timeout_s_;
};

}  // namespace anchorbench::estimator
