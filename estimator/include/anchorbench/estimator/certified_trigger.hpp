#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/credible_covariance.hpp"
#include "anchorbench/estimator/height_check.hpp"
#include "anchorbench/estimator/init_trigger.hpp"
#include "anchorbench/estimator/solver.hpp"
#include "anchorbench/estimator/tag_biases.hpp"
#include "anchorbench/estimator/triggers.hpp"

namespace anchorbench::estimator {

// The certificate's settings (the config's estimator.certificate).
struct CertificateOptions {
  double accuracy_m = 0.75;  // D: every anchor position farther than this from the estimate must be ruled out
  double confidence = 0.99;  // of the region that must lie within D
  // Its own geometric cadence (with trigger.evaluate_every), whatever the other solving triggers
  // use: a run then costs N g / (g - 1) samples' worth of solves, not O(N^2 / every).
  double evaluate_growth = 1.1;
  // Test 0's window: every estimate since this share of the data (from the last evaluation at or
  // before stable_since N) within D. 0.5: a doubling of the data; larger waits less after the
  // estimate settles (the latency to the oracle is at least 1 / stable_since) and sees less drift.
  double stable_since = 0.7;
  // Test 3, the region seen from the ends of its axes. Off only to measure what it buys (a sweep):
  // without it the UAV hall's radio biases and Table I certify anchors beyond 1 m.
  bool region_ends = true;
  // The covariance the certificate judges: its own, so that it stays honest where the reported
  // one is configured as the paper's (estimator.covariance).
  CovarianceOptions covariance;

  bool IsValid(std::string* why) const;
};

// The chi-square quantile with 3 degrees of freedom (Newton on the exact CDF from Wilson-Hilferty's
// start): the squared radius, in standard deviations, of a 3-D confidence region.
double ChiSquare3Quantile(double confidence);

// Ours (docs/method.md#the-certified-trigger): fire only once the data rule out, with the bias
// refit, every anchor position farther than D from the estimate. On its cadence it solves (the
// anchor's solver) and judges the estimate four ways, all without the truth (tested as 2-3, 1, 0:
// the cheap region first, and a mirror's verdict before the stability, so a refusal says why):
// 0. It must be stable: every estimate since a share of the data (stable_since; from the last
//    evaluation at or before that share of N) within D of it; an estimate that slides along a trade-off valley, or flips between basins,
//    is no certificate.
// 1. The mirror through the tags' plane must be ruled out: the fit is refined (L2 LM) from the
//    estimate's reflection, and the estimate must beat that fit by the mirror check's min_evidence
//    (FitEvidence, with the anchor's height prior if it has one), plus 2 ln(k) after k such tests
//    (a Bonferroni bound: two nearly equal fits tested again and again cross any fixed threshold
//    by chance; a near-flat Table I run did, at 9.4 after -6 and +3). A flat path is refused as
//    height_unobservable, never initialized on a confident mirror; and an estimate that sits in the
//    mirror's basin of a path that is not quite flat (its reflection refines to a better fit) is
//    not certified either. Where the refinement returns to the estimate, the plain reflection's
//    evidence counts (HeightCheckedSolver's test), unless the reflection with a region as large
//    as the estimate's lies within D (an anchor near the tags' plane: nothing farther than D to
//    rule out).
// 2. The credible covariance P (credible_covariance.hpp, with the certificate's own options: the
//    solver's, scaled for correlated noise, plus the model error and the consistency check's
//    travel bias) must put its
//    `confidence` region inside the ball of radius D: chi2_3(confidence) lambda_max(P) <= D^2.
// 3. So must the covariance seen from every end of that region's principal axes (6 points; unless
//    region_ends is off), with
//    the estimate's residual scale (floored at the model error): an early estimate can look well
//    conditioned from where it stands, and the region's ends are where a trade-off of range and
//    bias along a narrow cone of directions, or a line of tags, shows.
// With a known height (a height prior), the estimate's height must also agree with it within the
// two-sided `confidence` interval the model allows between them (test `height_prior`,
// PriorGapSigma): a prior-data conflict is an error the model does not hold.
// A line of tags or too narrow a cone leaves P singular or large: the trigger waits. Cost per
// evaluation: one solve, one mirror test and 7 O(N) passes; on a geometric cadence
// (evaluate_growth > 1) a whole run costs O(N), and a refusal that repeats (the mirror of a flat
// path or its height valley the solve crawls unconverged, a line's singular region) backs the
// cadence off (SolveCadence::BackOff).
class CertifiedTrigger : public InitTrigger {
 public:
  // `solver_options` give the L2 refinement of the mirror test its tolerances (the height prior is
  // the solver's, Solver::height_prior);
  // `tag_biases` are the initializer's, so that the certificate judges the estimate it will report.
  CertifiedTrigger(std::shared_ptr<const Solver> solver, const AnchorSolverOptions& solver_options,
                   const CertificateOptions& options, const HeightCheckOptions& mirror,
                   const TagBiasOptions& tag_biases, TravelBias travel_bias, SolveCadence cadence);
  bool Fire(const TriggerInput& in) override { return cadence_.Due(in); }
  bool Evaluate(const TriggerInput& in) override;
  std::optional<SolveStatus> refusal() const override { return refusal_; }
  // The last evaluation's tests (Judgement): which one held the anchor back and by how much.
  std::optional<Judgement> why_not() const override { return evaluations_ ? std::optional(judgement_) : std::nullopt; }
  std::size_t evaluations() const override { return evaluations_; }
  std::optional<RegionBasis> region_basis() const override { return basis_; }
  void AdoptJudged(SolveResult* solve) const override;

 private:
  struct Alternative {
    Eigen::Vector3d p_world_anchor;
    double bias_m;
    bool mirror;
  };
  enum class Verdict { kRuledOut, kMirror, kOtherMinimum };
  // The estimate's reflection through the tags' plane and the fit refined from it (L2): the basin
  // move and the alternatives both start there, so it is refined once per estimate.
  struct MirrorFit {
    Mirror mirror;
    SolveResult refined;  // where mirror.exists
  };
  // The estimate's residuals, read once per evaluation: their RMS, the correlation factor and the
  // consistency check's travel bias (credible_covariance.hpp); and the one-bias unit-weight
  // covariance (J^T J)^-1 of (p_A, gamma) at the estimate where a test reads it (several tags' share,
  // a height prior's gap), absent where singular.
  struct NoiseStats {
    double residual_scale_m;
    double correlation_factor;
    double travel_bias_m;
    std::optional<Eigen::Matrix4d> unit_covariance;
  };
  // The four tests on one evaluation; Evaluate adds the cadence's back-off.
  bool Judge(const TriggerInput& in);
  MirrorFit FitMirror(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                      const SolveResult& estimate) const;
  // An estimate in the worse of two mirror basins moved to the better one: where the fit refined
  // (L2) from its reflection (`mirror`, FitMirror's of the estimate) ends farther than D away, fits
  // better by the mirror check's min_evidence and is separated from it (Compare), that fit becomes
  // the estimate (true).
  bool MoveToBetterBasin(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                         std::span<const int> tag_id, const MirrorFit& mirror, SolveResult* estimate) const;
  // The cadence after the judgement: backed off on a refusal that repeats, restored on progress.
  void PaceCadence();
  // Where other minima of the fit may lie: the mirror (with its bias), 3 D along the covariance's
  // axes and towards and away from the tags' centroid, and the ranges read as distances (the
  // bias-free linear fit); RuleOutAlternatives gives these the bias that fits best there.
  std::vector<Alternative> Alternatives(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                                        const SolveResult& estimate, const Eigen::Matrix3d& axes,
                                        const Mirror& mirror) const;
  // Of how much worse the alternative at (p_world_fit, bias_fit_m) fits than the estimate, the
  // squares (m^2) a range error of the model error's size and the noise could make up, were the
  // alternative the anchor, at the certificate's confidence (ExplainedSquares in the .cpp: the
  // alternative as the anchor would start ahead by its separation). Zero without a model error.
  double ExplainedSquares(std::span<const Eigen::Vector3d> p_world_tag, const SolveResult& estimate,
                          const Eigen::Vector3d& p_world_fit, double bias_fit_m, double scale_m);
  // Fit a against fit b of the same data: a's evidence over b (FitEvidence after
  // `explained_squares`, plus the height prior's chi-square difference; where the tags' offsets are
  // estimated, FitEvidenceOwnOffsets: each fit with the offsets that suit it) and whether the two
  // can be told apart (separated(): a prior that alone reaches `threshold`, or a separation of
  // predicted ranges of at least min_separation in units of `scale_m`).
  FitComparison Compare(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                        std::span<const int> tag_id, const Eigen::Vector3d& p_a, double bias_a_m,
                        const Eigen::Vector3d& p_b, double bias_b_m,
                        double scale_m, double explained_squares, double threshold) const;
  // Each alternative refined (L2 LM; the mirror's refinement is `mirror`'s, FitMirror's of the
  // estimate); one that ends farther than D away must fit worse than the estimate by the evidence
  // threshold, and predict ranges that differ enough to tell. The weakest alternative's evidence and
  // the threshold go to the judgement.
  Verdict RuleOutAlternatives(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                              std::span<const int> tag_id, const SolveResult& estimate, const Eigen::Matrix3d& axes, double scale_m,
                              const MirrorFit& mirror);
  // 3.: the largest radius of the region seen from the ends of its axes (+inf where singular), with
  // the estimate's noise statistics (Judge computes them once).
  double RegionFromEnds(const TriggerInput& in, const SolveResult& estimate,
                        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>& axes, const NoiseStats& noise) const;
  // The standard deviation the model allows between the estimate's height and its prior (the test
  // `height_prior`).
  double PriorGapSigma(const TriggerInput& in, const SolveResult& estimate, const NoiseStats& noise) const;
  // What a forecast of the region needs from this evaluation (guidance.hpp).
  void KeepBasis(const SolveResult& estimate, const NoiseStats& noise);
  // The judgement's account of the region: each term's share of the largest variance.
  void ShareRegion(const TriggerInput& in, const SolveResult& noise_only, const NoiseStats& noise,
                   const Eigen::Vector3d& axis, double largest_variance);
  // The tags whose offsets are among the unknowns ({0}: one bias for all).
  std::vector<int> EstimatedTags(std::span<const int> tag_id, std::size_t samples) const;
  // The largest variance of the covariance seen from `point`, with `tags` as EstimatedTags gave
  // them, the estimate's travel bias and its height prior (information and weight,
  // credible_covariance.hpp); +infinity where it is singular.
  double LargestVariance(std::span<const Eigen::Vector3d> p_world_tag, std::span<const int> tag_id,
                         const std::vector<int>& tags, const Eigen::Vector3d& point, double noise_variance,
                         double travel_bias_m, double height_information, double height_weight) const;

  std::shared_ptr<const Solver> solver_;  // the anchor's
  NlsSolver refine_;                      // L2, for the mirror's basin
  std::optional<HeightPrior> height_prior_;  // the solver's
  HeightCheckOptions mirror_;
  TagBiasOptions tag_biases_;
  CertificateOptions options_;
  CovarianceOptions covariance_;
  TravelBias travel_bias_;
  SolveCadence cadence_;
  double region_chi2_;
  double prior_quantile_;    // the two-sided normal quantile at the confidence: the height prior's test
  double pattern_quantile_;  // the one-sided one: the model error's share of an alternative's evidence
  std::optional<SolveStatus> refusal_;
  std::optional<RegionBasis> basis_;  // the last evaluation's, for a forecast of the region
  Judgement judgement_;
  std::size_t evaluations_ = 0;
  struct Evaluated {
    std::size_t samples;
    Eigen::Vector3d p_world_anchor;
  };
  std::vector<Evaluated> history_;           // the evaluations since the last at or before half the data
  int tests_ = 0;                            // of the alternatives, for the threshold's 2 ln(k)
  static constexpr int kStructuralRepeats = 3;
  int structural_refusals_ = 0;              // since an estimate last got past the mirror
  bool converged_ = false;                   // the last evaluation's solve reached its minimum
  bool mirrored_ = false;                    // a mirror refused an estimate since one got past it
  double smallest_region_m_ = std::numeric_limits<double>::infinity();  // around a converged estimate
  std::vector<double> corrected_m_;          // the ranges less each tag's offset (scratch)
  std::vector<double> residual_m_;           // an alternative's residuals, for its bias (scratch)
  std::optional<SolveResult> judged_;        // the estimate of an evaluation that certified it
};

}  // namespace anchorbench::estimator
