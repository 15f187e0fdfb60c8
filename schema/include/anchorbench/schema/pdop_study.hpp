#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace anchorbench::schema {

// The PDOP triggers of Sec. III-C / IV-B, side by side (Figs. 6-8).
enum class PdopMethod { kClosestPoint, kLs, kNls, kTrue };
constexpr std::array<PdopMethod, 4> kPdopMethods = {PdopMethod::kClosestPoint, PdopMethod::kLs, PdopMethod::kNls,
                                                    PdopMethod::kTrue};
const char* PdopMethodName(PdopMethod method);  // closest_point | ls | nls | true

// One checkpoint of one anchor in one realization: the PDOP of every method on the accepted
// samples so far, and the errors of the LS and NLS estimates on them.
struct PdopCheckpoint {
  int realization = 0;
  int anchor_id = 0;
  int n = 0;                 // accepted samples so far
  double t_s = 0.0;          // since the anchor's first accepted range
  std::array<double, 4> pdop{};  // by PdopMethod; +inf where undefined
  double bias_aware_dop = 0.0;   // true, with the bias column (CRLB / sigma_d)
  // The online bias-aware proxies (docs/method.md): the closest-point DOP with a bias column
  // (dop4_closest_point), and the worst bias-aware DOP over the confidence region of the NLS
  // estimate (dop4_confidence, trigger.confidence_sigmas); +inf where undefined.
  double dop4_closest_point = 0.0;
  double dop4_confidence = 0.0;
  std::optional<double> ls_error_m, nls_error_m;
};

// Over every accepted sample (not only checkpoints): how often the closest-point PDOP was below
// the true PDOP (both finite), and by how much. "Ideal" is Theorem 3.1's exact setting: the
// closest-point PDOP computed with the true distances (so p_C is the truly closest sample), split
// by whether the theorem's precondition ||p_k - p_C|| <= ||p_k - p_A|| holds for all k.
struct UnderestimateStats {
  long samples = 0;  // with both values finite
  long below = 0;    // estimate (measured ranges) < true
  double worst_ratio = 1.0;
  std::vector<double> ratios_below;  // estimate / true where below (for quantiles)
  long ideal_below = 0;
  long ideal_samples_precondition = 0;
  long ideal_below_precondition = 0;

  void Add(const UnderestimateStats& other);  // other's samples after this one's
};

// The certified trigger (ours) on the same samples, beside the probe: when it fired, on how many
// samples, and the error of the estimate it reported; or why it did not (its refusal, or "waiting").
struct CertifiedOutcome {
  int realization = 0;
  int anchor_id = 0;
  std::optional<double> t_s;  // since the anchor's first accepted range; empty if it never fired
  int n = 0;
  std::optional<double> error_m;
  std::string status;  // the event's status, or the trigger's refusal, or "waiting"
};

// The PDOP study's settings (anchorbench pdop-study; the config's pdop_study, which --every and
// --bin-s set): absent from a config, these defaults.
struct PdopStudyConfig {
  int every = 10;       // a checkpoint (LS and NLS solves) every this many accepted samples
  double bin_s = 10.0;  // the summary's time bins (pdop_study.md: Fig. 7's first 120 s)
  bool IsValid(std::string* why) const;
};

struct PdopStudy {
  std::vector<PdopCheckpoint> checkpoints;  // realization by realization, anchor by anchor
  std::vector<CertifiedOutcome> certified;  // in the same order, one per anchor
  UnderestimateStats stats;
  int anchors = 0;  // over all realizations
};

}  // namespace anchorbench::schema
