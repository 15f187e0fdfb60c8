#include "anchorbench/estimator/certified_trigger.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

#include "anchorbench/estimator/ls_solver.hpp"
#include "numerics.hpp"

namespace anchorbench::estimator {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kStartDistance = 3.0;    // the alternatives' starts, in units of D from the estimate
constexpr int kAlternativeIterations = 20;

// The median of d_k - |p_k - p|: the bias that fits best at p (robust to outliers); `r` is scratch.
double MedianResidual(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                      const Eigen::Vector3d& p_world_anchor, std::vector<double>& r) {
  r.resize(range_m.size());
  for (std::size_t k = 0; k < range_m.size(); ++k) r[k] = range_m[k] - (p_world_tag[k] - p_world_anchor).norm();
  std::nth_element(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(r.size() / 2), r.end());
  return r.empty() ? 0.0 : r[r.size() / 2];
}

// The standard normal quantile (Acklam's rational approximation, |error| < 1.2e-9).
double NormalQuantile(double p) {
  constexpr double a[] = {-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02,
                          1.383577518672690e+02, -3.066479806614716e+01, 2.506628277459239e+00};
  constexpr double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                          6.680131188771972e+01, -1.328068155288572e+01};
  constexpr double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                          -2.549732539343734e+00, 4.374664141464968e+00, 2.938163982698783e+00};
  constexpr double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00, 3.754408661907416e+00};
  constexpr double kLow = 0.02425;
  if (p < kLow) {
    const double q = std::sqrt(-2.0 * std::log(p));
    return (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
           ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  }
  if (p > 1.0 - kLow) return -NormalQuantile(1.0 - p);
  const double q = p - 0.5, r = q * q;
  return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
         (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
}

// The reflection of `point` through the vertical plane through `centroid` along the tags' longest
// horizontal spread.
Eigen::Vector3d SideMirror(std::span<const Eigen::Vector3d> p_world_tag, const Eigen::Vector3d& centroid,
                           const Eigen::Vector3d& point) {
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const Eigen::Vector3d& p : p_world_tag) {
    const Eigen::Vector2d d = (p - centroid).head<2>();
    scatter.noalias() += d * d.transpose();
  }
  const Eigen::Vector2d along = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(scatter).eigenvectors().col(1);
  const Eigen::Vector3d normal(-along.y(), along.x(), 0.0);
  return point - 2.0 * (point - centroid).dot(normal) * normal;
}

}  // namespace

bool CertificateOptions::IsValid(std::string* why) const {
  if (!(accuracy_m > 0.0 && accuracy_m <= 1000.0)) {
    if (why) *why = "accuracy_m must be in (0, 1000]";
    return false;
  }
  if (!(evaluate_growth > 1.0 && evaluate_growth <= 10.0)) {
    if (why) *why = "evaluate_growth must be in (1, 10]";
    return false;
  }
  if (!(stable_since >= 0.1 && stable_since <= 0.95)) {
    if (why) *why = "stable_since must be in [0.1, 0.95]";
    return false;
  }
  if (!(confidence >= 0.5 && confidence <= 0.9999)) {
    if (why) *why = "confidence must be in [0.5, 0.9999]";
    return false;
  }
  return covariance.IsValid(why);
}

double ChiSquare3Quantile(double confidence) {
  // Wilson-Hilferty's start, then Newton on the exact CDF with 3 degrees of freedom:
  // F(x) = erf(sqrt(x/2)) - sqrt(2x/pi) exp(-x/2), F'(x) = sqrt(x/(2 pi)) exp(-x/2).
  constexpr double k = 3.0;
  const double z = NormalQuantile(confidence);
  const double t = 1.0 - 2.0 / (9.0 * k) + z * std::sqrt(2.0 / (9.0 * k));
  double x = std::max(k * t * t * t, 1e-6);
  for (int i = 0; i < 8; ++i) {
    const double cdf = std::erf(std::sqrt(x / 2.0)) - std::sqrt(2.0 * x / std::numbers::pi) * std::exp(-x / 2.0);
    const double pdf = std::sqrt(x / (2.0 * std::numbers::pi)) * std::exp(-x / 2.0);
    x = std::max(x - (cdf - confidence) / pdf, 1e-6);
  }
  return x;
}

namespace {

// (J^T J)^-1 of (p_A, gamma) with one bias, at `point`; none where singular.
std::optional<Eigen::Matrix4d> UnitCovariance(std::span<const Eigen::Vector3d> p_world_tag,
                                              const Eigen::Vector3d& point) {
  const Eigen::MatrixXd information = TagInformation(p_world_tag, {}, {0}, point);
  Eigen::Matrix4d inverse;
  if (!internal::InvertNormalMatrix(information.topLeftCorner<4, 4>(), &inverse)) return std::nullopt;
  return inverse;
}

NlsOptions L2(NlsOptions nls) {
  nls.kernel = KernelMode::kL2;
  nls.max_iterations = std::min(nls.max_iterations, kAlternativeIterations);
  return nls;
}

}  // namespace

CertifiedTrigger::CertifiedTrigger(std::shared_ptr<const Solver> solver, const AnchorSolverOptions& solver_options,
                                   const CertificateOptions& options, const HeightCheckOptions& mirror,
                                   const TagBiasOptions& tag_biases, TravelBias travel_bias, SolveCadence cadence)
    : solver_(std::move(solver)),
      refine_(L2(solver_options.nls)),
      height_prior_(solver_->height_prior()),
      mirror_(mirror),
      tag_biases_(tag_biases),
      options_(options),
      covariance_(options.covariance),
      travel_bias_(std::move(travel_bias)),
      cadence_(cadence),
      region_chi2_(ChiSquare3Quantile(options.confidence)),
      prior_quantile_(NormalQuantile(0.5 + 0.5 * options.confidence)),
      pattern_quantile_(NormalQuantile(options.confidence)) {
  if (tag_biases_.estimate) covariance_.link_offset_m = 0.0;  // estimated: SolveWithTagBiases' own term
}

std::vector<CertifiedTrigger::Alternative> CertifiedTrigger::Alternatives(std::span<const Eigen::Vector3d> p_world_tag,
                                                                         std::span<const double> range_m,
                                                                         const SolveResult& estimate,
                                                                         const Eigen::Matrix3d& axes,
                                                                         const Mirror& mirror) const {
  std::vector<Alternative> starts;
  if (mirror.exists) starts.push_back({mirror.p_world_mirror, mirror.bias_mirror_m, true});
  // Along each principal axis of the covariance, and towards and away from the tags: where range
  // and bias trade off (one side of an anchor seen), the other minima of the fit lie that way.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : p_world_tag) centroid += p / static_cast<double>(p_world_tag.size());
  Eigen::Vector3d towards_tags = centroid - estimate.p_world_anchor;
  const double step_m = kStartDistance * options_.accuracy_m;
  std::vector<Eigen::Vector3d> directions = {axes.col(0), axes.col(1), axes.col(2)};
  if (towards_tags.norm() > 1e-9) directions.push_back(towards_tags.normalized());
  for (const Eigen::Vector3d& direction : directions) {
    for (const double side : {-1.0, 1.0}) starts.push_back({estimate.p_world_anchor + side * step_m * direction, 0.0, false});
  }
  // The ranges read as plain distances (bias 0): a far anchor seen from a short path trades
  // distance for bias along a valley whose minima lie metres apart at nearly equal fits (a Table I
  // run: 9.9 m off with a bias of 5.7 m, certified, where the zero-bias end fitted better).
  if (const std::optional<Eigen::Vector3d> bias_free = SolveBiasFreeLs(p_world_tag, range_m)) {
    starts.push_back({*bias_free, 0.0, false});
  }
  // With a known height, a path along a line leaves one more twin: the reflection through the
  // vertical plane along the path (a turn about the line at the same height). Where the path is
  // not a line, the twin refines back or fits clearly worse.
  if (height_prior_) starts.push_back({SideMirror(p_world_tag, centroid, estimate.p_world_anchor), 0.0, false});
  return starts;
}

CertifiedTrigger::Verdict CertifiedTrigger::RuleOutAlternatives(std::span<const Eigen::Vector3d> p_world_tag,
                                                                std::span<const double> range_m,
                                                                std::span<const int> tag_id,
                                                                const SolveResult& estimate,
                                                                const Eigen::Matrix3d& axes, double scale_m,
                                                                const MirrorFit& mirror) {
  ++tests_;
  const double threshold = mirror_.min_evidence + 2.0 * std::log(static_cast<double>(tests_));
  judgement_.evidence_needed = threshold;
  judgement_.evidence = kInf;  // none farther than D: nothing to rule out
  for (Alternative start : Alternatives(p_world_tag, range_m, estimate, axes, mirror.mirror)) {
    // Each start's bias only once it is reached: the first alternative not ruled out ends the loop
    // (on a flat path, the mirror, every evaluation).
    if (!start.mirror) start.bias_m = MedianResidual(p_world_tag, range_m, start.p_world_anchor, residual_m_);
    Alternative fit = start;
    const SolveResult refined = start.mirror ? mirror.refined
        : refine_.Solve(p_world_tag, range_m, start.p_world_anchor, start.bias_m, height_prior_);
    if (Succeeded(refined.status)) {
      fit.p_world_anchor = refined.p_world_anchor;
      fit.bias_m = refined.bias_m;
    }
    // The estimate's own basin (the mirror: also its plain reflection, HeightCheckedSolver's test,
    // unless the reflection's region, as large as the estimate's, lies within D too: an anchor near
    // the tags' plane, both readings and all around them within D, nothing farther to rule out).
    const double apart_m = (fit.p_world_anchor - estimate.p_world_anchor).norm();
    if (apart_m <= options_.accuracy_m) {
      const double mirror_apart_m = (start.p_world_anchor - estimate.p_world_anchor).norm();
      if (!start.mirror || mirror_apart_m + judgement_.region_m <= options_.accuracy_m) continue;
      fit = start;
    }
    const double explained_squares = ExplainedSquares(p_world_tag, estimate, fit.p_world_anchor, fit.bias_m, scale_m);
    const FitComparison comparison = Compare(p_world_tag, range_m, tag_id, estimate.p_world_anchor, estimate.bias_m,
                                          fit.p_world_anchor, fit.bias_m, scale_m, explained_squares, threshold);
    // Too close to tell counts as no evidence at all.
    const double evidence = comparison.separated() ? comparison.evidence : 0.0;
    if (evidence < judgement_.evidence) {
      judgement_.evidence = evidence;
      judgement_.evidence_explained = comparison.separated() ? comparison.explained : 0.0;
    }
    if (!comparison.separated() || !(comparison.evidence >= threshold)) {
      judgement_.samples_needed = comparison.SamplesNeeded();
      return start.mirror ? Verdict::kMirror : Verdict::kOtherMinimum;
    }
  }
  return Verdict::kRuledOut;
}

double CertifiedTrigger::ExplainedSquares(std::span<const Eigen::Vector3d> p_world_tag, const SolveResult& estimate,
                                          const Eigen::Vector3d& p_world_fit, double bias_fit_m, double scale_m) {
  // Were the alternative the anchor, the ranges would read its predictions plus a pattern e and
  // noise n, and the estimate's squares would exceed its own by sum d_k^2 - 2 sum d_k (e_k + n_k),
  // d the difference of the two fits' predicted ranges. For the estimate to fit better by what was
  // observed, the pattern and the noise must make up that difference AND the sum d_k^2 the
  // alternative starts ahead by: 2 sum d_k (e_k + n_k) has the standard deviation
  // 2 sqrt(S^2 + s^2 sum d_k^2) (S: PatternCovariation, s: the residual scale), taken at the
  // one-sided `confidence`; what the alternative starts ahead by is counted over the samples the
  // trimmed evidence keeps (the smallest 1 - trim_fraction of the d_k^2, conservative: trimming
  // drops the estimate's largest squares, where d is largest). Ours; until this round the whole
  // 2 z S came off the evidence, as if the alternative as the anchor would fit only as well as the
  // estimate, which held anchors near the tags' plane back although their reflection fitted worse
  // by more than any pattern of the model's size explains. Without any discount, on a real field a
  // robot's turn read 0.2 m long at the true anchor made its twin across the path fit better by an
  // evidence of 168, and the twin was certified.
  const double pattern_m2 = PatternCovariation(p_world_tag, estimate.p_world_anchor, estimate.bias_m, p_world_fit,
                                               bias_fit_m, covariance_);
  if (!(pattern_m2 > 0.0)) return 0.0;  // no model error: the threshold and the separation judge the noise
  std::vector<double>& d = residual_m_;  // the two fits' predicted ranges apart
  d.resize(p_world_tag.size());
  double all_m2 = 0.0;
  for (std::size_t k = 0; k < d.size(); ++k) {
    d[k] = (p_world_tag[k] - estimate.p_world_anchor).norm() + estimate.bias_m - (p_world_tag[k] - p_world_fit).norm() -
           bias_fit_m;
    all_m2 += d[k] * d[k];
  }
  const double kept_m2 = TrimmedSquaresInPlace(d, mirror_.trim_fraction);
  return std::max(0.0, 2.0 * pattern_quantile_ * std::sqrt(pattern_m2 * pattern_m2 + scale_m * scale_m * all_m2) - kept_m2);
}

FitComparison CertifiedTrigger::Compare(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                                        std::span<const int> tag_id, const Eigen::Vector3d& p_a, double bias_a_m,
                                        const Eigen::Vector3d& p_b, double bias_b_m, double scale_m,
                                        double explained_squares, double threshold) const {
  const double prior_evidence = height_prior_ ? height_prior_->Chi2(p_b.z()) - height_prior_->Chi2(p_a.z()) : 0.0;
  double explained = 0.0;
  // The ranges are corrected by the estimate's offsets of the tags (SolveWithTagBiases): each fit is
  // judged with offsets of its own, or the estimate would win by the offsets it chose for itself.
  const std::span<const int> own_offsets =
      EstimatedTags(tag_id, range_m.size()).size() > 1 ? tag_id : std::span<const int>();
  const double evidence = FitEvidenceOwnOffsets(p_world_tag, range_m, own_offsets, p_a, bias_a_m, p_b, bias_b_m,
                                                mirror_.trim_fraction, explained_squares, &explained) +
                          prior_evidence;
  // A likelihood ratio's own spread grows with the separation it measures (about 2 sqrt(lambda),
  // more with noise in the tag positions: on the flat floor, 1 cm of it swung a lambda ~10 fit
  // from -15 to +28): only a separation no swing crosses counts as evidence, or a height prior
  // that alone rules the alternative out (a twin at the same height, a line's, it cannot).
  const double separation =
      prior_evidence >= threshold ? kInf : Separation(p_world_tag, p_a, bias_a_m, p_b, bias_b_m, scale_m);
  return {evidence, threshold, separation, mirror_.min_separation, range_m.size(), explained};
}

std::vector<int> CertifiedTrigger::EstimatedTags(std::span<const int> tag_id, std::size_t samples) const {
  return OffsetTags(tag_id, samples, tag_biases_.estimate);
}

double CertifiedTrigger::LargestVariance(std::span<const Eigen::Vector3d> p_world_tag, std::span<const int> tag_id,
                                         const std::vector<int>& tags, const Eigen::Vector3d& point,
                                         double noise_variance, double travel_bias_m, double height_information,
                                         double height_weight) const {
  // The noise part: the (p_A, gamma) block of the information's inverse, with each tag's offset
  // among the unknowns where they are estimated (tag_biases.hpp), and the prior's information.
  const Eigen::MatrixXd information =
      TagInformation(p_world_tag, tags.size() > 1 ? tag_id : std::span<const int>(), tags, point);
  return LargestPositionVariance(information, noise_variance, height_information,
                                 ModelErrorCovariance(p_world_tag, tag_id, point, covariance_, travel_bias_m, height_weight));
}

void CertifiedTrigger::KeepBasis(const SolveResult& estimate, const NoiseStats& noise) {
  const double scale_m = std::max(noise.residual_scale_m, covariance_.model_error_m);  // as RegionFromEnds
  basis_ = RegionBasis{estimate.p_world_anchor,
                       noise.correlation_factor * scale_m * scale_m,
                       noise.travel_bias_m,
                       estimate.height_information,
                       estimate.height_weight,
                       tag_biases_.estimate,
                       region_chi2_,
                       options_.accuracy_m,
                       covariance_};
}

double CertifiedTrigger::RegionFromEnds(const TriggerInput& in, const SolveResult& estimate,
                                      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>& axes,
                                      const NoiseStats& noise) const {
  const std::span<const Eigen::Vector3d> p_world_tag = in.p_world_tag;
  const double limit = options_.accuracy_m * options_.accuracy_m / region_chi2_;  // of the largest variance
  // From the ends of the region's axes, with the estimate's noise (floored at the model error)
  // scaled for its correlation.
  const double scale_m = std::max(noise.residual_scale_m, covariance_.model_error_m);
  const std::vector<int> tags = EstimatedTags(in.tag_id, p_world_tag.size());
  double worst = 0.0;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d half_axis =
        std::sqrt(region_chi2_ * std::max(axes.eigenvalues()(i), 0.0)) * axes.eigenvectors().col(i);
    for (const double side : {-1.0, 1.0}) {
      const Eigen::Vector3d end = estimate.p_world_anchor + side * half_axis;
      const double variance = LargestVariance(p_world_tag, in.tag_id, tags, end, noise.correlation_factor * scale_m * scale_m,
                                              noise.travel_bias_m, estimate.height_information, estimate.height_weight);
      if (!(variance <= limit)) return std::sqrt(region_chi2_ * variance);  // the first end beyond D decides
      worst = std::max(worst, variance);
    }
  }
  return std::sqrt(region_chi2_ * worst);
}

double CertifiedTrigger::PriorGapSigma(const TriggerInput& in, const SolveResult& estimate,
                                       const NoiseStats& noise) const {
  // The solve pulls the height from the ranges' own z_r towards the prior by 1 / (1 + w a), a the
  // ranges' unit-weight z variance [(J^T J)^-1]_zz and w the prior's weight (rank-one update of the
  // normal equations), so z - z_prior = (z_r - z_prior) / (1 + w a), and z_r - z_prior has the
  // ranges' variance (noise, model error) plus the prior's.
  const double prior_variance = 1.0 / estimate.height_information;
  if (!noise.unit_covariance) return std::sqrt(prior_variance);
  const double a = (*noise.unit_covariance)(2, 2);
  const double model =
      ModelErrorCovariance(in.p_world_tag, in.tag_id, estimate.p_world_anchor, covariance_, noise.travel_bias_m)(2, 2);
  const double pull = 1.0 + estimate.height_weight * a;
  const double noise_variance = noise.correlation_factor * noise.residual_scale_m * noise.residual_scale_m;
  return std::sqrt(noise_variance * a + model + prior_variance) / pull;
}

void CertifiedTrigger::ShareRegion(const TriggerInput& in, const SolveResult& noise_only, const NoiseStats& stats,
                                   const Eigen::Vector3d& axis, double largest_variance) {
  const double correlation_factor = stats.correlation_factor;
  // Along the region's longest axis v, each term's v^T P v. The noise part's tags' offsets are
  // what the joint information with them adds to the one-bias information's inverse.
  const double noise = axis.dot(noise_only.covariance.topLeftCorner<3, 3>() * axis);
  const double correlated =
      axis.dot(ScaleRangeNoise(noise_only.covariance, noise_only.height_information, correlation_factor)
                   .topLeftCorner<3, 3>() * axis);
  double tags_part = 0.0;
  const std::vector<int> tags = EstimatedTags(in.tag_id, in.p_world_tag.size());
  if (tags.size() > 1 && stats.unit_covariance) {
    const double scale_m = stats.residual_scale_m;
    tags_part = std::clamp(noise - scale_m * scale_m * axis.dot(stats.unit_covariance->topLeftCorner<3, 3>() * axis),
                           0.0, noise);
  }
  const ModelErrorTerms terms = ModelErrorCovarianceTerms(in.p_world_tag, in.tag_id, noise_only.p_world_anchor,
                                                          covariance_, stats.travel_bias_m, noise_only.height_weight);
  const double parts[] = {noise - tags_part, correlated - noise, axis.dot(terms.model.topLeftCorner<3, 3>() * axis),
                          axis.dot(terms.travel.topLeftCorner<3, 3>() * axis), axis.dot(terms.links.topLeftCorner<3, 3>() * axis),
                          correlation_factor * tags_part};
  const double total = std::max(parts[0] + parts[1] + parts[2] + parts[3] + parts[4] + parts[5], 1e-300);
  judgement_.share_noise = parts[0] / total;
  judgement_.share_correlation = parts[1] / total;
  judgement_.share_model_error = parts[2] / total;
  judgement_.share_travel_bias = parts[3] / total;
  judgement_.share_link_offsets = parts[4] / total;
  judgement_.share_tag_offsets = parts[5] / total;
  judgement_.region_m = std::sqrt(region_chi2_ * largest_variance);
}

bool CertifiedTrigger::Evaluate(const TriggerInput& in) {
  const bool certified = Judge(in);
  PaceCadence();
  return certified;
}

void CertifiedTrigger::PaceCadence() {
  // A refusal that will not move with a few more samples (a flat path's mirror, a line's failed
  // solve or unbounded region, a region around an estimate the solve left short of its minimum:
  // the same valley crawled again) is structural: from the kStructuralRepeats-th in a row on, ask
  // later each time (SolveCadence::BackOff). Progress restores the cadence: an estimate past the
  // region and the mirror, or, before any mirror, a converged estimate's region smaller than any
  // before. Any other finite region neither counts nor restores (on a flat path it wanders).
  const std::string_view test = judgement_.blocked_by;
  const bool region = test == "region" || test == "region_ends";
  if (test == "mirror") mirrored_ = true;
  if (test == "solve" || test == "mirror" || (region && (!std::isfinite(judgement_.value) || !converged_))) {
    if (++structural_refusals_ >= kStructuralRepeats) cadence_.BackOff();
    return;
  }
  const bool smaller = region && judgement_.value < smallest_region_m_;
  if (smaller) smallest_region_m_ = judgement_.value;
  if (!region || (smaller && !mirrored_)) {
    structural_refusals_ = 0;
    mirrored_ = false;
    cadence_.Resume();
  }
}

bool CertifiedTrigger::Judge(const TriggerInput& in) {
  ++evaluations_;
  judgement_ = Judgement{};
  basis_.reset();
  judged_.reset();
  judgement_.t_s = in.t_s;
  judgement_.samples = in.range_m.size();
  const double d_m = options_.accuracy_m;
  auto blocked = [this](std::string_view test, double value, double limit) {
    judgement_.blocked_by = test;
    judgement_.value = value;
    judgement_.limit = limit;
    return false;
  };
  // Every test below on the ranges as the solve fitted them: less each tag's offset.
  TriggerInput fitted = in;
  SolveResult estimate =
      SolveWithTagBiases(*solver_, in.p_world_tag, in.range_m, in.tag_id, tag_biases_, nullptr, &corrected_m_);
  if (!Succeeded(estimate.status)) {
    converged_ = false;
    return blocked("solve", Judgement::kNone, Judgement::kNone);
  }
  fitted.range_m = corrected_m_;
  std::optional<MirrorFit> mirror = FitMirror(fitted.p_world_tag, fitted.range_m, estimate);
  // A moved estimate has a mirror of its own, fitted where the alternatives need it.
  if (MoveToBetterBasin(fitted.p_world_tag, fitted.range_m, fitted.tag_id, *mirror, &estimate)) mirror.reset();
  converged_ = estimate.status == SolveStatus::kConverged;
  const SolveResult noise_only = estimate;
  // The residuals' terms at the estimate, once: for its covariance here and the tests below.
  const CredibleTerms terms = CredibleTermsOf(fitted.p_world_tag, fitted.range_m, fitted.tag_id, covariance_,
                                              travel_bias_, estimate.p_world_anchor, estimate.bias_m);
  MakeCredible(fitted.p_world_tag, fitted.tag_id, covariance_, terms, &estimate);
  // 0. Stable since a share of the data (stable_since; half: a doubling): every estimate from the
  // last evaluation at or before that share of N on within D of this one. An estimate that slides
  // along a trade-off valley as data come (a wall anchor seen from the room, range against bias)
  // moves by more than D over the window.
  history_.push_back({in.range_m.size(), estimate.p_world_anchor});
  std::size_t first = 0;
  const double since = options_.stable_since * static_cast<double>(in.range_m.size());
  while (first + 1 < history_.size() && static_cast<double>(history_[first + 1].samples) <= since) ++first;
  history_.erase(history_.begin(), history_.begin() + static_cast<std::ptrdiff_t>(first));
  const bool doubled = static_cast<double>(history_.front().samples) <= since;
  double spread_m = 0.0;
  for (const Evaluated& e : history_) spread_m = std::max(spread_m, (e.p_world_anchor - estimate.p_world_anchor).norm());
  judgement_.stability_m = spread_m;
  // The cheap test first (the region), then the alternatives' fits (whose verdict says why an
  // estimate is refused: a mirror is height_unobservable), then the stability.
  const Eigen::Matrix3d covariance = estimate.covariance.topLeftCorner<3, 3>();
  if (!covariance.allFinite()) return blocked("region", kInf, d_m);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(covariance);
  // The residuals' statistics at the estimate, once for every test below.
  const bool reads_unit_covariance = height_prior_ || EstimatedTags(in.tag_id, in.range_m.size()).size() > 1;
  const NoiseStats noise{
      ResidualScale(fitted.p_world_tag, fitted.range_m, noise_only.p_world_anchor, noise_only.bias_m),
      terms.correlation_factor, terms.travel_bias_m,
      reads_unit_covariance ? UnitCovariance(fitted.p_world_tag, noise_only.p_world_anchor) : std::nullopt};
  ShareRegion(fitted, noise_only, noise, axes.eigenvectors().col(2), axes.eigenvalues()(2));
  KeepBasis(estimate, noise);
  const double limit = d_m * d_m / region_chi2_;  // of the largest variance
  if (!(axes.eigenvalues().maxCoeff() <= limit)) return blocked("region", judgement_.region_m, d_m);
  if (options_.region_ends) {
    const double from_ends_m = RegionFromEnds(fitted, estimate, axes, noise);
    if (!(from_ends_m <= d_m)) return blocked("region_ends", from_ends_m, d_m);
  }
  // A known height the estimate disagrees with beyond what the model lets the two differ by (or
  // the prior's own interval) means an error the model does not hold: on a real field, the anchors
  // whose ranges pulled z 3-8 sigma off the survey were the ones 0.8-1.1 m off. Wait until the
  // data agree.
  if (height_prior_) {
    const double off_m = std::abs(estimate.p_world_anchor.z() - height_prior_->z_world_m);
    // Never wider than the prior's own interval: an estimate outside it says the prior is wrong,
    // and the certificate rests on it.
    const double limit_m =
        prior_quantile_ * std::min(height_prior_->sigma_m, PriorGapSigma(fitted, noise_only, noise));
    if (!(off_m <= limit_m)) return blocked("height_prior", off_m, limit_m);
  }
  if (!mirror) mirror = FitMirror(fitted.p_world_tag, fitted.range_m, estimate);
  const Verdict verdict = RuleOutAlternatives(fitted.p_world_tag, fitted.range_m, fitted.tag_id, estimate,
                                              axes.eigenvectors(), noise.residual_scale_m, *mirror);
  refusal_ = verdict == Verdict::kMirror ? std::optional(SolveStatus::kHeightUnobservable) : std::nullopt;
  if (verdict == Verdict::kMirror) return blocked("mirror", judgement_.evidence, judgement_.evidence_needed);
  if (verdict == Verdict::kOtherMinimum) return blocked("alternative", judgement_.evidence, judgement_.evidence_needed);
  if (!doubled) {
    return blocked("doubling", static_cast<double>(in.range_m.size()),
                   static_cast<double>(history_.front().samples) / options_.stable_since);
  }
  if (!(spread_m <= d_m)) return blocked("stability", spread_m, d_m);
  judgement_.blocked_by = {};
  judged_ = noise_only;
  return true;
}

CertifiedTrigger::MirrorFit CertifiedTrigger::FitMirror(std::span<const Eigen::Vector3d> p_world_tag,
                                                        std::span<const double> range_m,
                                                        const SolveResult& estimate) const {
  MirrorFit fit{MirrorOf(p_world_tag, range_m, estimate, mirror_.trim_fraction), {}};
  if (fit.mirror.exists) {
    fit.refined = refine_.Solve(p_world_tag, range_m, fit.mirror.p_world_mirror, fit.mirror.bias_mirror_m, height_prior_);
  }
  return fit;
}

bool CertifiedTrigger::MoveToBetterBasin(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                                         std::span<const int> tag_id, const MirrorFit& mirror,
                                         SolveResult* estimate) const {
  // A solve started from the linear fit can settle in the worse basin of a mirror pair and stay
  // there as data come (a cone approach, a nearly flat path with a little height). The move only
  // picks the basin the tests judge: the other one must still be ruled out like any alternative
  // (RuleOutAlternatives, with the model error's discount, which picking a basin does not need).
  if (!mirror.mirror.exists) return false;
  const SolveResult& refined = mirror.refined;
  if (!Succeeded(refined.status) ||
      (refined.p_world_anchor - estimate->p_world_anchor).norm() <= options_.accuracy_m) {
    return false;  // no other basin farther than D
  }
  const FitComparison comparison =
      Compare(p_world_tag, range_m, tag_id, refined.p_world_anchor, refined.bias_m, estimate->p_world_anchor, estimate->bias_m,
              ResidualScale(p_world_tag, range_m, refined.p_world_anchor, refined.bias_m), 0.0, mirror_.min_evidence);
  if (!(comparison.evidence >= mirror_.min_evidence) || !comparison.separated()) return false;
  *estimate = refined;
  return true;
}

void CertifiedTrigger::AdoptJudged(SolveResult* solve) const {
  if (!judged_) return;
  if (Succeeded(solve->status) && (solve->p_world_anchor - judged_->p_world_anchor).norm() <= options_.accuracy_m) return;
  *solve = *judged_;
}

}  // namespace anchorbench::estimator
