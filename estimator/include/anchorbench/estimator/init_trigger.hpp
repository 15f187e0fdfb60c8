#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string_view>

#include <Eigen/Core>

#include "anchorbench/estimator/guidance.hpp"
#include "anchorbench/estimator/solve_result.hpp"

namespace anchorbench::estimator {

// What a trigger sees after every accepted sample of its anchor, until the anchor is initialized.
struct TriggerInput {
  double t_s = 0.0;        // this sample's time
  double t_first_s = 0.0;  // the anchor's first accepted sample
  // Accepted samples the trigger has seen, this one included: FeedResult::n_accepted less those
  // queued behind a pending solve (they come later) and those after the initialization.
  std::size_t n_admitted = 0;
  Eigen::Vector3d sample_p_world_tag = Eigen::Vector3d::Zero();  // this sample
  double sample_range_m = 0.0;
  // The buffered samples so far, this one last: every accepted sample, unless the initializer's
  // buffer reached its cap (InitializerOptions::max_buffered_samples) and thinned them.
  std::span<const Eigen::Vector3d> p_world_tag;
  std::span<const double> range_m;
  std::span<const int> tag_id;
  double pdop = 0.0;  // the closest-point PDOP of Eq. (4) over all accepted samples (+inf if undefined)
  // Whether the initializer would solve if the trigger fired now (min_samples reached, not waiting
  // for more data after a failed solve). Costly triggers evaluate only then; all may update state.
  bool eligible = false;
};

// Why a trigger has not fired: the test that holds the anchor back, its number and the limit that
// number must meet ("pdop" 1.7 against 1.0). The certified trigger fills the rest from each of its
// evaluations: its region's radius and each term's share of it, the weakest alternative's evidence,
// the stability spread (docs/method.md#why-not-yet). NaN where a number does not apply.
struct Judgement {
  static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  double t_s = kNone;          // of the sample judged
  std::size_t samples = 0;     // buffered samples judged
  std::string_view blocked_by;  // the test, a static name; empty: it fired
  double value = kNone;        // the test's number
  double limit = kNone;        // what it must reach (at most, or at least: the test's own sense)
  // The certificate's region: the radius of its confidence region (m) and each term's share of
  // the largest variance (they sum to 1): the noise, the correlation factor's inflation of it, the
  // model error, the consistency check's travel bias, the links' and the tags' offsets.
  double region_m = kNone;
  double share_noise = kNone, share_correlation = kNone, share_model_error = kNone, share_travel_bias = kNone,
         share_link_offsets = kNone, share_tag_offsets = kNone;
  double evidence = kNone, evidence_needed = kNone;  // the weakest alternative's fit evidence, and the threshold
  // Of how much worse that alternative fits, the part the model error could explain, already off
  // `evidence` (FitComparison::explained): evidence + evidence_explained is the fits' own difference.
  double evidence_explained = kNone;
  double stability_m = kNone;                        // the largest move of the estimate since half the data
  // `mirror` from the mirror check of a solve (FitComparison): the samples at which it would pass
  // if the data went on as they have; +infinity where more of the same will not settle it.
  double samples_needed = kNone;
};

// `test` holds the anchor back with `value` against `limit`, judged at t_s on `samples` buffered.
inline Judgement BlockedBy(std::string_view test, double value, double limit, double t_s, std::size_t samples) {
  Judgement j;
  j.t_s = t_s;
  j.samples = samples;
  j.blocked_by = test;
  j.value = value;
  j.limit = limit;
  return j;
}

// A solve the mirror check refused, judged at t_s: `mirror`, the evidence against its threshold,
// and the samples that would settle it.
inline Judgement MirrorJudgement(const FitComparison& refusal, double t_s) {
  Judgement j = BlockedBy("mirror", refusal.evidence, refusal.evidence_needed, t_s, refusal.samples);
  j.evidence = refusal.evidence;
  j.evidence_needed = refusal.evidence_needed;
  j.evidence_explained = refusal.explained;
  j.samples_needed = refusal.SamplesNeeded();
  return j;
}

// When to initialize an anchor (Sec. III-C): one interface, so the paper's comparisons (closest-
// point PDOP vs the PDOP at the LS or NLS estimate vs the true PDOP vs a fixed window) are a
// configuration choice. One instance per anchor; it may keep state between samples.
//
// A decision has two steps, so that an initializer with deferred solves keeps every O(N) step out
// of Feed(): Fire() runs after every accepted sample and is O(1); a trigger that solves for an
// estimate (pdop_ls, pdop_nls, dop4_confidence, certified) answers true there when its cadence is
// due, and decides in Evaluate(), O(N), which the initializer runs where it runs its solves
// (inline, or in RunPendingSolve() / WorkPendingSolve()). While an evaluation or a solve is pending
// the trigger sees no other call: the samples that arrive meanwhile reach Fire() afterwards, in
// order, so deferred and inline decisions are the same.
class InitTrigger {
 public:
  virtual ~InitTrigger() = default;

  // Called after every accepted sample until the anchor is initialized, O(1): true to solve now,
  // or, for a trigger that solves, to evaluate now.
  virtual bool Fire(const TriggerInput& input) = 0;

  // After Fire() returned true, on the same input (its buffered data unchanged): true to solve.
  // O(N) for a trigger that solves; the others fire on Fire() alone.
  virtual bool Evaluate(const TriggerInput& /*input*/) { return true; }

  // False for the fixed-window baseline: it never fires online, and the initializer solves once,
  // on all of the anchor's data, at Finish().
  virtual bool online() const { return true; }

  // Why it has not fired, where it can say more than "not triggered" (the certified trigger: the
  // mirror of its last estimate could not be ruled out, kHeightUnobservable).
  virtual std::optional<SolveStatus> refusal() const { return std::nullopt; }

  // Why it has not fired yet, as of the last sample or evaluation it judged; nothing where it has
  // no test of its own (a fixed window, a count). A trigger that solves counts its evaluations, so
  // that each one can be reported (AnchorInitializer::TakeJudgements).
  virtual std::optional<Judgement> why_not() const { return std::nullopt; }
  virtual std::size_t evaluations() const { return 0; }
  // What a forecast of its region needs from its last evaluation (guidance.hpp), where it judges a
  // region and its last evaluation reached one (a solve that succeeded).
  virtual std::optional<RegionBasis> region_basis() const { return std::nullopt; }
  // Right after Evaluate() returned true, on the initializer's solve of the same data: a trigger
  // that judged an estimate of its own (the certified trigger, which may move its estimate to the
  // better of two mirror basins) puts it in place of a solve that failed or lies farther than its
  // accuracy from it, so that what is reported is what was judged. The others leave it.
  virtual void AdoptJudged(SolveResult* /*solve*/) const {}
};

}  // namespace anchorbench::estimator
