#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <string>

#include "anchorbench/estimator/closest_point_pdop.hpp"
#include "anchorbench/estimator/init_trigger.hpp"
#include "anchorbench/estimator/solver.hpp"

namespace anchorbench::estimator {

// The paper's trigger (Sec. III-C): the closest-point PDOP of Eq. (4) below a threshold, O(1).
class ClosestPointPdopTrigger : public InitTrigger {
 public:
  explicit ClosestPointPdopTrigger(double threshold) : threshold_(threshold) {}
  bool Fire(const TriggerInput& in) override {
    last_ = {in.t_s, in.range_m.size(), in.pdop};
    return in.eligible && in.pdop < threshold_;
  }
  std::optional<Judgement> why_not() const override { return last_.Judged("pdop", threshold_); }

 private:
  double threshold_;
  struct Last {
    double t_s = Judgement::kNone;
    std::size_t samples = 0;
    double value = Judgement::kNone;
    std::optional<Judgement> Judged(std::string_view test, double limit) const {
      if (samples == 0) return std::nullopt;
      return BlockedBy(test, value, limit, t_s, samples);
    }
  } last_;
};

// When a trigger that solves for an estimate evaluates: at the first eligible sample, then once
// at least `every` more samples were accepted and the count has grown by the factor `growth`
// (the config's trigger.evaluate_every, evaluate_growth).
class SolveCadence {
 public:
  SolveCadence(int every, double growth) : every_(static_cast<std::size_t>(every)), growth_(growth) {}
  bool Due(const TriggerInput& in) {
    if (!in.eligible) return false;
    const double growth = 1.0 + (growth_ - 1.0) * static_cast<double>(1 << back_off_);
    if (evaluated_at_ != 0 && (in.n_admitted < evaluated_at_ + every_ ||
                               static_cast<double>(in.n_admitted) < growth * static_cast<double>(evaluated_at_))) {
      return false;
    }
    evaluated_at_ = in.n_admitted;
    return true;
  }
  // A verdict that repeats (a flat path's mirror, a line's singular region) is asked again later
  // each time: growth - 1 doubles per repeat, up to kMaxBackOff doublings (x32); Resume() undoes it. A
  // refusal then costs O(N) with a smaller constant, and a fixed cadence (growth 1) stays fixed.
  void BackOff() { back_off_ = std::min(back_off_ + 1, kMaxBackOff); }
  void Resume() { back_off_ = 0; }

 private:
  static constexpr int kMaxBackOff = 5;
  std::size_t every_;
  double growth_;
  int back_off_ = 0;
  std::size_t evaluated_at_ = 0;  // sample count of the last evaluation (0: none yet)
};

// Sec. IV-B's alternatives: Eqs. (2)-(3) at the current estimate of a solver (LS, or the NLS the
// anchor is initialized with), re-solved on the cadence.
class EstimatePdopTrigger : public InitTrigger {
 public:
  EstimatePdopTrigger(std::shared_ptr<const Solver> solver, double threshold, SolveCadence cadence)
      : solver_(std::move(solver)), threshold_(threshold), cadence_(cadence) {}
  bool Fire(const TriggerInput& in) override { return cadence_.Due(in); }
  bool Evaluate(const TriggerInput& in) override;
  std::optional<Judgement> why_not() const override { return judgement_; }

 private:
  std::shared_ptr<const Solver> solver_;
  double threshold_;
  SolveCadence cadence_;
  std::optional<Judgement> judgement_;  // of the last evaluation: `pdop`, or why its solve failed
};

// Ours: a closest-point DOP other than the paper's, O(1) per sample: Eq. (4)'s rows with the bias
// as a fourth column (dop4_closest_point), or their x-y block alone, the DOP with the height known
// (hdop_closest_point, for a height prior on a flat path). It keeps its own sums rather than read
// the initializer's: with deferred solves the initializer admits queued samples after its
// closest-point sums have moved on, and the trigger must see the geometry as of each sample it
// judges.
class ClosestPointDopTrigger : public InitTrigger {
 public:
  using Value = double (ClosestPointPdop::*)() const;
  ClosestPointDopTrigger(Value value, double threshold, std::string_view test = "dop")
      : value_(value), threshold_(threshold), test_(test) {}
  bool Fire(const TriggerInput& in) override {
    dop_.Add(in.sample_p_world_tag, in.sample_range_m);
    last_t_s_ = in.t_s;
    last_samples_ = in.range_m.size();
    return in.eligible && (dop_.*value_)() < threshold_;
  }
  std::optional<Judgement> why_not() const override {
    if (last_samples_ == 0) return std::nullopt;
    return BlockedBy(test_, (dop_.*value_)(), threshold_, last_t_s_, last_samples_);
  }

 private:
  ClosestPointPdop dop_;
  Value value_;
  double threshold_;
  std::string_view test_;
  double last_t_s_ = Judgement::kNone;
  std::size_t last_samples_ = 0;
};

// Ours, after a prototype described in issue 13: the estimate that looks well conditioned from
// where it stands may be wrong, so judge the geometry from every corner of its confidence region.
// On its cadence it solves (the anchor's solver), and takes the worst bias-aware
// DOP at the estimate and at +-`sigmas` standard deviations along each principal axis of the
// position covariance (7 points, O(N) each). It fires when that worst case is below the threshold.
class ConfidenceRegionDopTrigger : public InitTrigger {
 public:
  ConfidenceRegionDopTrigger(std::shared_ptr<const Solver> solver, double threshold, SolveCadence cadence, double sigmas)
      : solver_(std::move(solver)), threshold_(threshold), cadence_(cadence), sigmas_(sigmas) {}
  bool Fire(const TriggerInput& in) override { return cadence_.Due(in); }
  bool Evaluate(const TriggerInput& in) override;
  std::optional<Judgement> why_not() const override { return judgement_; }

 private:
  std::shared_ptr<const Solver> solver_;
  double threshold_;
  SolveCadence cadence_;
  double sigmas_;
  std::optional<Judgement> judgement_;  // of the last evaluation: `dop4`, or why its solve failed
};

// The worst bias-aware DOP over the estimate and the 6 ends of the principal axes of its
// position covariance scaled by `sigmas` (+inf if the covariance is not finite).
double WorstBiasAwareDop(std::span<const Eigen::Vector3d> p_world_tag, const SolveResult& estimate, double sigmas);

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
  bool Fire(const TriggerInput& in) override { return in.eligible && in.n_admitted >= count_; }

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
