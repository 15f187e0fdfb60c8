#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/estimator/solve_result.hpp"

namespace anchorbench::estimator {

// What an initialized anchor's covariance includes beyond the solver's noise-only one (ours,
// docs/method.md#credible-covariances). A navigation filter fuses the anchor with it, so it must
// cover the errors that do not shrink with more data:
// - the model error: the direction-dependent range bias of real antennas, which a constant bias
//   and white noise miss. It is taken as a random smooth function on the sphere of directions from
//   the anchor, spanned by the real spherical harmonics of degrees 1..model_error_degree with
//   equal variances, of RMS model_error_m. Degree 1 is a pure shift of the anchor (no geometry
//   can see it); higher degrees are amplified where the geometry is thin.
// - the travel bias of the consistency check (Sec. III-B): it truncates the noise of the range
//   differences on one side, so accepted ranges read short while the tag recedes and long while
//   it approaches, by beta = g(tau / q) q (ConsistencyFilter::TravelBias), which moves an anchor
//   along the direction of travel (12 mm at tau = 2 sigma = 0.2 m on Table I's passes). q is the
//   scale of consecutive residual differences (DifferenceScale): the check truncates white noise,
//   never a slow bias, which cancels in the differences.
// - per-link offsets: a multi-tag robot's tags range to an anchor with offsets of their own (0.1-0.3
//   m on public recordings) that one bias cannot absorb; with two or more tags in the data, each
//   tag's samples share a constant error of sigma link_offset_m.
// - correlated noise: the same check also correlates the accepted noise from sample to sample
//   (lag-1 autocorrelation ~0.2 at tau = 2 sigma), and slowly varying biases do more; the noise-only
//   covariance, which takes the samples as independent, is scaled by the Bartlett-weighted sum of
//   the residuals' autocorrelations, f = 1 + 2 sum_{l=1..L} (1 - l/(L+1)) rho_l (L = 10, residuals
//   clipped at 3 robust sigmas, f in [1, 10]).
// The first three enter as range errors e = E c with c ~ N(0, I): the estimate moves by
// A^-1 J^T E c, with A = J^T J and rows j_k = [-u_k^T, 1] at the estimate (u_k the unit direction
// anchor -> tag), so
//   P = f P_solver + A^-1 (J^T E)(J^T E)^T A^-1.
struct CovarianceOptions {
  double model_error_m = 0.05;  // RMS of the direction-dependent range error; 0: none
  int model_error_degree = 2;   // 1 to 3
  bool travel_bias = true;      // the consistency check's travel bias (0 where no check runs)
  double link_offset_m = 0.1;   // sigma of each tag's own offset, with two or more tags and the
                                // offsets not estimated (tag_biases.hpp: estimated, their own term)
  bool correlated_noise = true; // the autocorrelation factor f

  bool IsValid(std::string* why) const;
};

// The real spherical harmonics of degrees 1..degree (3, 8 or 15 of them) at a unit vector, each
// of mean square 1 over the sphere; `out` holds (degree + 1)^2 - 1 values.
void Harmonics(const Eigen::Vector3d& unit, int degree, double* out);
int HarmonicCount(int degree);

// The added part A^-1 (J^T E)(J^T E)^T A^-1 for an estimate (p_A, gamma), 4x4 over (p_A, gamma);
// the travel term needs the samples in time order, the link term their tags (empty: one tag).
// With a height prior, A = J^T J + height_weight e_z e_z^T (SolveResult::height_weight): the
// prior holds the height against a range error as the solve weighs it against the ranges. Zero
// where A is singular or nothing is added.
Eigen::Matrix4d ModelErrorCovariance(std::span<const Eigen::Vector3d> p_world_tag, std::span<const int> tag_id,
                                     const Eigen::Vector3d& p_world_anchor, const CovarianceOptions& options,
                                     double travel_bias_m, double height_weight = 0.0);

// The sums the added part is built from, over the samples at an anchor position: A = J^T J and,
// for each kind of range error, J^T of its pattern (each harmonic, the travel bias's signs, each
// tag's indicator with two or more tags). ModelErrorCovariance is AddedCovariance(SumErrorRows(..));
// a forecast of the certificate's region (guidance.hpp) adds samples to the sums first.
struct ErrorSums {
  static constexpr int kMaxHarmonics = 15;
  Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
  int harmonics = 0;  // 0: no model error
  Eigen::Matrix<double, 4, kMaxHarmonics> jt_harmonics = Eigen::Matrix<double, 4, kMaxHarmonics>::Zero();
  bool travel = false;
  Eigen::Vector4d jt_travel = Eigen::Vector4d::Zero();
  std::vector<int> tags;                  // the tags in the data where there are two or more (links)
  std::vector<Eigen::Vector4d> jt_links;  // one per tag in `tags`

  // `count` samples more from `p_world_tag`, of the tag `tags[tag_index]` (none: an index past
  // the end), standing still (no travel bias). O(1).
  void Add(const Eigen::Vector3d& p_world_tag, const Eigen::Vector3d& p_world_anchor, int model_error_degree,
           double count, std::size_t tag_index);
  // The same for a row j = [-u, 1] of the direction u anchor -> tag (SumErrorRows' samples).
  void AddRow(const Eigen::Vector3d& unit, const Eigen::Vector4d& j, int model_error_degree, double count,
              std::size_t tag_index);
};
ErrorSums SumErrorRows(std::span<const Eigen::Vector3d> p_world_tag, std::span<const int> tag_id,
                       const Eigen::Vector3d& p_world_anchor, const CovarianceOptions& options, double travel_bias_m);
Eigen::Matrix4d AddedCovariance(const ErrorSums& sums, const CovarianceOptions& options, double travel_bias_m,
                                double height_weight = 0.0);

// The same split by kind (they sum to ModelErrorCovariance up to rounding): for the certificate's
// account of what its region is made of.
struct ModelErrorTerms {
  Eigen::Matrix4d model = Eigen::Matrix4d::Zero();
  Eigen::Matrix4d travel = Eigen::Matrix4d::Zero();
  Eigen::Matrix4d links = Eigen::Matrix4d::Zero();
};
ModelErrorTerms ModelErrorCovarianceTerms(std::span<const Eigen::Vector3d> p_world_tag, std::span<const int> tag_id,
                                          const Eigen::Vector3d& p_world_anchor, const CovarianceOptions& options,
                                          double travel_bias_m, double height_weight = 0.0);

// The largest eigenvalue of the position block of the region's covariance: noise_variance times the
// (p_A, gamma) block of the inverse of `information` (unit weights, of (p_A, gamma) and any tag
// offsets after them), or with a height prior's information the inverse of information /
// noise_variance plus it on z, plus `added` (the model error's part). +infinity where singular.
double LargestPositionVariance(const Eigen::MatrixXd& information, double noise_variance, double height_information,
                               const Eigen::Matrix4d& added);

// A covariance with the ranges' noise scaled by `factor` (the correlation factor f): f P without
// a prior; with one, (P^-1 - Lambda) / f + Lambda inverted, so the prior's information stays as it
// is (a correlated range noise does not make a surveyed height less certain).
Eigen::Matrix4d ScaleRangeNoise(const Eigen::Matrix4d& covariance, double height_information, double factor);

// How much the model error could move a comparison of two fits: the standard deviation of
// sum_k e_k d_k, with d_k the difference of the ranges fits a and b predict and e the model error's
// range errors as seen from a (the harmonics above, RMS model_error_m), in m^2. Two fits' squared
// residuals differ by 2 sum_k e_k d_k when e is added to the ranges.
double PatternCovariation(std::span<const Eigen::Vector3d> p_world_tag, const Eigen::Vector3d& p_a, double bias_a_m,
                          const Eigen::Vector3d& p_b, double bias_b_m, const CovarianceOptions& options);

// f above, from the range residuals of an estimate in time order.
double CorrelationFactor(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                         const Eigen::Vector3d& p_world_anchor, double bias_m);

// The residual scale the travel bias is judged against: the RMS of the range residuals of an
// estimate, with its N - 4 degrees of freedom.
double ResidualScale(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                     const Eigen::Vector3d& p_world_anchor, double bias_m);

// The scale the consistency check's truncation acts on: the RMS of the differences of consecutive
// residuals of one tag (pooled over the tags), over sqrt(2), clipped at 3 RMS twice so that the few
// outliers the check lets through do not count (and scaled back to a Gaussian's RMS); 0 with
// fewer than two of a tag.
double DifferenceScale(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                       std::span<const int> tag_id, const Eigen::Vector3d& p_world_anchor, double bias_m);

// The filter's travel bias for a difference scale and a sample's slack (OutlierFilter::TravelBias;
// none: 0).
using TravelBias = std::function<double(double difference_scale_m, double slack_m)>;

// The travel bias of these samples seen from `p_world_anchor` (ours): the RMS over the samples of
// the filter's bias at each one's slack, s_k = ||p_k - p_prev|| - |r_k - r_prev| >= 0 against the
// previous sample of its tag (the check's reference: the buffer holds the accepted samples). The
// check allows a range difference of ||p_k - p_prev|| + tau, so motion across the line of sight
// loosens it by s_k and truncates less (scripts/travel_bias_slack.py). travel_bias(q, 0) where no
// tag has two samples.
double TravelBiasOf(std::span<const Eigen::Vector3d> p_world_tag, std::span<const int> tag_id,
                    const Eigen::Vector3d& p_world_anchor, double difference_scale_m, const TravelBias& travel_bias);

// What the residuals of an estimate make of its covariance: the correlation factor f (1 without
// correlated_noise) and the travel bias (0 without travel_bias or a filter's TravelBias).
struct CredibleTerms {
  double correlation_factor = 1.0;
  double travel_bias_m = 0.0;
};
CredibleTerms CredibleTermsOf(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                              std::span<const int> tag_id, const CovarianceOptions& options,
                              const TravelBias& travel_bias, const Eigen::Vector3d& p_world_anchor, double bias_m);

// A successful solve's covariance made credible: f P_solver + the model error's part, with the
// terms read at the solve (CredibleTermsOf), or given where the caller has them already.
void MakeCredible(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                  std::span<const int> tag_id, const CovarianceOptions& options, const TravelBias& travel_bias,
                  SolveResult* solve);
void MakeCredible(std::span<const Eigen::Vector3d> p_world_tag, std::span<const int> tag_id,
                  const CovarianceOptions& options, const CredibleTerms& terms, SolveResult* solve);

}  // namespace anchorbench::estimator
