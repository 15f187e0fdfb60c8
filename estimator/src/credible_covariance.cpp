#include "anchorbench/estimator/credible_covariance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "anchorbench/estimator/tag_biases.hpp"
#include "numerics.hpp"

namespace anchorbench::estimator {
namespace {

constexpr int kMaxDegree = 3;

// The unit direction anchor -> tag and its row j = [-u^T, 1] of the range Jacobian.
struct JacobianRow {
  Eigen::Vector3d unit;
  Eigen::Vector4d j;
};
bool RowAt(const Eigen::Vector3d& p_world_tag, const Eigen::Vector3d& p_world_anchor, JacobianRow* row) {
  const Eigen::Vector3d diff = p_world_tag - p_world_anchor;
  const double distance_m = diff.norm();
  if (!(distance_m > 0.0)) return false;
  row->unit = diff / distance_m;
  row->j << -row->unit, 1.0;
  return true;
}

// Whether the range to the anchor grows from the sample before to the sample after k (+1, -1; 0
// at the ends and where it is still): the sign the consistency check's travel bias takes.
double RangeRateSign(std::span<const Eigen::Vector3d> p_world_tag, const Eigen::Vector3d& p_world_anchor, std::size_t k) {
  if (k == 0 || k + 1 >= p_world_tag.size()) return 0.0;
  const double change = (p_world_tag[k + 1] - p_world_anchor).norm() - (p_world_tag[k - 1] - p_world_anchor).norm();
  return change > 0.0 ? 1.0 : change < 0.0 ? -1.0 : 0.0;
}

// Calls step(previous, k) for every sample k and the sample before it of the same tag (one tag for
// all where tag_id does not cover the samples).
template <typename Step>
void ForEachTagStep(std::span<const int> tag_id, std::size_t samples, Step step) {
  struct Last {
    int tag_id;
    std::size_t k;
  };
  std::vector<Last> last;  // one per tag: a handful at most
  const bool tagged = tag_id.size() == samples;
  for (std::size_t k = 0; k < samples; ++k) {
    const int tag = tagged ? tag_id[k] : 0;
    const auto it = std::find_if(last.begin(), last.end(), [tag](const Last& l) { return l.tag_id == tag; });
    if (it == last.end()) {
      last.push_back({tag, k});
      continue;
    }
    step(it->k, k);
    it->k = k;
  }
}

}  // namespace

bool CovarianceOptions::IsValid(std::string* why) const {
  if (!(model_error_m >= 0.0 && model_error_m <= 10.0)) {
    if (why) *why = "model_error_m must be in [0, 10]";
    return false;
  }
  if (model_error_degree < 1 || model_error_degree > kMaxDegree) {
    if (why) *why = "model_error_degree must be 1, 2 or 3";
    return false;
  }
  if (!(link_offset_m >= 0.0 && link_offset_m <= 100.0)) {
    if (why) *why = "link_offset_m must be in [0, 100]";
    return false;
  }
  return true;
}

int HarmonicCount(int degree) { return (degree + 1) * (degree + 1) - 1; }

void Harmonics(const Eigen::Vector3d& u, int degree, double* out) {
  // Real orthonormal harmonics times sqrt(4 pi): mean square 1 over the sphere.
  const double x = u.x(), y = u.y(), z = u.z();
  const double s3 = std::sqrt(3.0), s15 = std::sqrt(15.0);
  out[0] = s3 * x;
  out[1] = s3 * y;
  out[2] = s3 * z;
  if (degree < 2) return;
  out[3] = s15 * x * y;
  out[4] = s15 * y * z;
  out[5] = s15 * x * z;
  out[6] = 0.5 * std::sqrt(5.0) * (3.0 * z * z - 1.0);
  out[7] = 0.5 * s15 * (x * x - y * y);
  if (degree < 3) return;
  const double a = std::sqrt(35.0 / 8.0), b = std::sqrt(105.0), c = std::sqrt(21.0 / 8.0), d = std::sqrt(7.0);
  out[8] = a * y * (3.0 * x * x - y * y);
  out[9] = b * x * y * z;
  out[10] = c * y * (5.0 * z * z - 1.0);
  out[11] = 0.5 * d * z * (5.0 * z * z - 3.0);
  out[12] = c * x * (5.0 * z * z - 1.0);
  out[13] = 0.5 * b * z * (x * x - y * y);
  out[14] = a * x * (x * x - 3.0 * y * y);
}

ErrorSums SumErrorRows(std::span<const Eigen::Vector3d> p_world_tag, std::span<const int> tag_id,
                        const Eigen::Vector3d& p_world_anchor, const CovarianceOptions& options, double travel_bias_m) {
  ErrorSums sums;
  sums.harmonics = options.model_error_m > 0.0 ? HarmonicCount(options.model_error_degree) : 0;
  sums.travel = options.travel_bias && travel_bias_m != 0.0;
  // The tags in the data, a handful at most (a robot's); one tag's offset is the bias itself.
  if (options.link_offset_m > 0.0 && tag_id.size() == p_world_tag.size()) {
    std::vector<int> tags = TagsInOrder(tag_id);
    if (tags.size() >= 2) {
      sums.tags = std::move(tags);
      sums.jt_links.assign(sums.tags.size(), Eigen::Vector4d::Zero());
    }
  }
  if (sums.harmonics == 0 && !sums.travel && sums.tags.empty()) return sums;
  for (std::size_t k = 0; k < p_world_tag.size(); ++k) {
    JacobianRow row;
    if (!RowAt(p_world_tag[k], p_world_anchor, &row)) continue;
    const std::size_t link = sums.tags.empty() ? 0
        : static_cast<std::size_t>(std::find(sums.tags.begin(), sums.tags.end(), tag_id[k]) - sums.tags.begin());
    sums.AddRow(row.unit, row.j, options.model_error_degree, 1.0, link);
    if (sums.travel) sums.jt_travel += row.j * RangeRateSign(p_world_tag, p_world_anchor, k);
  }
  return sums;
}

void ErrorSums::Add(const Eigen::Vector3d& p_world_tag, const Eigen::Vector3d& p_world_anchor, int model_error_degree,
                    double count, std::size_t tag_index) {
  JacobianRow row;
  if (RowAt(p_world_tag, p_world_anchor, &row)) AddRow(row.unit, row.j, model_error_degree, count, tag_index);
}

void ErrorSums::AddRow(const Eigen::Vector3d& unit, const Eigen::Vector4d& j, int model_error_degree, double count,
                       std::size_t tag_index) {
  // count * j once (each sum below multiplies it as it did when written count * j * ...), and the
  // harmonics' count read once: the stores into the sums may alias it.
  const Eigen::Vector4d counted_j = count * j;
  const int harmonic_count = harmonics;
  a.noalias() += counted_j * j.transpose();
  if (harmonic_count > 0) {
    double y[kMaxHarmonics];
    Harmonics(unit, model_error_degree, y);
    for (int h = 0; h < harmonic_count; ++h) jt_harmonics.col(h) += counted_j * y[h];
  }
  if (tag_index < jt_links.size()) jt_links[tag_index] += counted_j;
}

namespace {

// The added terms' range errors projected on the solve, J^T E E^T J for each kind, and A^-1.
struct ProjectedTerms {
  bool any = false;
  Eigen::Matrix4d a_inverse = Eigen::Matrix4d::Zero();
  Eigen::Matrix4d model = Eigen::Matrix4d::Zero(), travel = Eigen::Matrix4d::Zero(), links = Eigen::Matrix4d::Zero();
  Eigen::Matrix4d total = Eigen::Matrix4d::Zero();  // the three, summed in the order the reported covariance always has
};

ProjectedTerms Project(const ErrorSums& sums, const CovarianceOptions& options, double travel_bias_m,
                       double height_weight) {
  ProjectedTerms out;
  const int harmonics = sums.harmonics;
  if (harmonics == 0 && !sums.travel && sums.tags.empty()) return out;
  Eigen::Matrix4d a = sums.a;
  a(2, 2) += height_weight;  // a height prior holds the height against the errors as it does against noise
  if (!internal::InvertNormalMatrix(a, &out.a_inverse)) return out;
  out.any = true;
  if (harmonics > 0) {  // equal variances: the RMS over the sphere is model_error_m
    const double variance = options.model_error_m * options.model_error_m / harmonics;
    out.model.noalias() = variance * sums.jt_harmonics.leftCols(harmonics) * sums.jt_harmonics.leftCols(harmonics).transpose();
    out.total.noalias() += variance * sums.jt_harmonics.leftCols(harmonics) * sums.jt_harmonics.leftCols(harmonics).transpose();
  }
  if (sums.travel) {
    out.travel.noalias() = travel_bias_m * travel_bias_m * sums.jt_travel * sums.jt_travel.transpose();
    out.total.noalias() += travel_bias_m * travel_bias_m * sums.jt_travel * sums.jt_travel.transpose();
  }
  for (const Eigen::Vector4d& jt : sums.jt_links) {
    out.links.noalias() += options.link_offset_m * options.link_offset_m * jt * jt.transpose();
    out.total.noalias() += options.link_offset_m * options.link_offset_m * jt * jt.transpose();
  }
  return out;
}

ProjectedTerms Project(std::span<const Eigen::Vector3d> p_world_tag, std::span<const int> tag_id,
                       const Eigen::Vector3d& p_world_anchor, const CovarianceOptions& options, double travel_bias_m,
                       double height_weight) {
  return Project(SumErrorRows(p_world_tag, tag_id, p_world_anchor, options, travel_bias_m), options, travel_bias_m,
                 height_weight);
}

}  // namespace

double LargestPositionVariance(const Eigen::MatrixXd& information, double noise_variance, double height_information,
                               const Eigen::Matrix4d& added) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  // The prior's information beside the ranges' (height_information = 0: none; the plain scaling
  // keeps the bytes of runs without one).
  Eigen::MatrixXd weighed = information;
  double scale = noise_variance;
  if (height_information > 0.0) {
    weighed /= noise_variance;
    weighed(2, 2) += height_information;
    scale = 1.0;
  }
  Eigen::Matrix4d noise;
  if (weighed.rows() == 4) {
    if (!internal::InvertNormalMatrix(weighed.topLeftCorner<4, 4>(), &noise)) return kInfinity;
  } else {
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(weighed);
    if (ldlt.info() != Eigen::Success) return kInfinity;
    noise = ldlt.solve(Eigen::MatrixXd::Identity(weighed.rows(), weighed.cols())).topLeftCorner<4, 4>();
  }
  const Eigen::Matrix4d p = scale * noise + added;
  const Eigen::Matrix3d position = p.topLeftCorner<3, 3>();
  if (!position.allFinite() || !(position.diagonal().minCoeff() > 0.0)) return kInfinity;
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(position, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
}

Eigen::Matrix4d AddedCovariance(const ErrorSums& sums, const CovarianceOptions& options, double travel_bias_m,
                                double height_weight) {
  const ProjectedTerms t = Project(sums, options, travel_bias_m, height_weight);
  if (!t.any) return Eigen::Matrix4d::Zero();
  return t.a_inverse * t.total * t.a_inverse;
}

Eigen::Matrix4d ModelErrorCovariance(std::span<const Eigen::Vector3d> p_world_tag, std::span<const int> tag_id,
                                     const Eigen::Vector3d& p_world_anchor, const CovarianceOptions& options,
                                     double travel_bias_m, double height_weight) {
  const ProjectedTerms t = Project(p_world_tag, tag_id, p_world_anchor, options, travel_bias_m, height_weight);
  if (!t.any) return Eigen::Matrix4d::Zero();
  return t.a_inverse * t.total * t.a_inverse;
}

ModelErrorTerms ModelErrorCovarianceTerms(std::span<const Eigen::Vector3d> p_world_tag, std::span<const int> tag_id,
                                          const Eigen::Vector3d& p_world_anchor, const CovarianceOptions& options,
                                          double travel_bias_m, double height_weight) {
  const ProjectedTerms t = Project(p_world_tag, tag_id, p_world_anchor, options, travel_bias_m, height_weight);
  ModelErrorTerms terms;
  if (!t.any) return terms;
  terms.model = t.a_inverse * t.model * t.a_inverse;
  terms.travel = t.a_inverse * t.travel * t.a_inverse;
  terms.links = t.a_inverse * t.links * t.a_inverse;
  return terms;
}

double PatternCovariation(std::span<const Eigen::Vector3d> p_world_tag, const Eigen::Vector3d& p_a, double bias_a_m,
                          const Eigen::Vector3d& p_b, double bias_b_m, const CovarianceOptions& options) {
  if (!(options.model_error_m > 0.0)) return 0.0;
  const int harmonics = HarmonicCount(options.model_error_degree);
  constexpr int kMaxHarmonics = ErrorSums::kMaxHarmonics;
  Eigen::Matrix<double, kMaxHarmonics, 1> projection = Eigen::Matrix<double, kMaxHarmonics, 1>::Zero();
  double y[kMaxHarmonics];
  for (const Eigen::Vector3d& p : p_world_tag) {
    const Eigen::Vector3d diff = p - p_a;
    const double distance_m = diff.norm();
    if (!(distance_m > 0.0)) continue;
    const double d = distance_m + bias_a_m - (p - p_b).norm() - bias_b_m;
    Harmonics(diff / distance_m, options.model_error_degree, y);
    for (int h = 0; h < harmonics; ++h) projection(h) += y[h] * d;
  }
  // Each harmonic's coefficient has variance model_error_m^2 / harmonics.
  return options.model_error_m / std::sqrt(static_cast<double>(harmonics)) * projection.head(harmonics).norm();
}

double CorrelationFactor(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                         const Eigen::Vector3d& p_world_anchor, double bias_m) {
  constexpr std::size_t kMaxLag = 10;
  constexpr double kClip = 3.0, kMaxFactor = 10.0;
  const std::size_t n = range_m.size();
  if (n < 4 * kMaxLag) return 1.0;  // too few residuals for their autocorrelations
  std::vector<double> r(n);
  for (std::size_t k = 0; k < n; ++k) r[k] = (p_world_tag[k] - p_world_anchor).norm() + bias_m - range_m[k];
  std::vector<double> magnitude(n);
  for (std::size_t k = 0; k < n; ++k) magnitude[k] = std::abs(r[k]);
  std::nth_element(magnitude.begin(), magnitude.begin() + static_cast<std::ptrdiff_t>(n / 2), magnitude.end());
  const double clip = kClip * 1.4826 * magnitude[n / 2];  // outliers would decide the correlations
  double mean = 0.0;
  for (double& v : r) {
    v = std::clamp(v, -clip, clip);
    mean += v;
  }
  mean /= static_cast<double>(n);
  double variance = 0.0;
  for (double& v : r) {
    v -= mean;
    variance += v * v;
  }
  if (!(variance > 0.0)) return 1.0;
  double factor = 1.0;
  for (std::size_t lag = 1; lag <= kMaxLag; ++lag) {
    double covariance = 0.0;
    for (std::size_t k = lag; k < n; ++k) covariance += r[k] * r[k - lag];
    factor += 2.0 * (1.0 - static_cast<double>(lag) / (kMaxLag + 1)) * covariance / variance;
  }
  return std::clamp(factor, 1.0, kMaxFactor);
}

double ResidualScale(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                     const Eigen::Vector3d& p_world_anchor, double bias_m) {
  if (range_m.size() <= 4) return 0.0;
  double squares = 0.0;
  for (std::size_t k = 0; k < range_m.size(); ++k) {
    const double r = (p_world_tag[k] - p_world_anchor).norm() + bias_m - range_m[k];
    squares += r * r;
  }
  return std::sqrt(squares / static_cast<double>(range_m.size() - 4));
}

double DifferenceScale(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                       std::span<const int> tag_id, const Eigen::Vector3d& p_world_anchor, double bias_m) {
  // The RMS of the differences, then twice that of those within kClip RMS of the last (ours): the
  // check truncates the noise's Gaussian core, and the few outliers it lets through (a few per
  // thousand on a ground robot's log) would double an RMS and, through g, the travel bias.
  constexpr double kClip = 3.0;
  constexpr double kClippedRms = 0.98658;  // of a unit Gaussian within +-3: sqrt(1 - 6 phi(3) / (2 Phi(3) - 1))
  auto residual = [&](std::size_t k) { return (p_world_tag[k] - p_world_anchor).norm() + bias_m - range_m[k]; };
  auto rms_within = [&](double limit_m) {
    double squares = 0.0;
    std::size_t count = 0;
    ForEachTagStep(tag_id, range_m.size(), [&](std::size_t previous, std::size_t k) {
      const double change_m = residual(k) - residual(previous);
      if (!(std::abs(change_m) <= limit_m)) return;
      squares += change_m * change_m;
      ++count;
    });
    return count > 0 ? std::sqrt(squares / static_cast<double>(count)) : 0.0;
  };
  double rms_m = rms_within(std::numeric_limits<double>::infinity());
  for (int pass = 0; pass < 2 && rms_m > 0.0; ++pass) rms_m = rms_within(kClip * rms_m) / kClippedRms;
  return rms_m / std::sqrt(2.0);
}

double TravelBiasOf(std::span<const Eigen::Vector3d> p_world_tag, std::span<const int> tag_id,
                    const Eigen::Vector3d& p_world_anchor, double difference_scale_m, const TravelBias& travel_bias) {
  double squares = 0.0;
  std::size_t count = 0;
  ForEachTagStep(tag_id, p_world_tag.size(), [&](std::size_t previous, std::size_t k) {
    const Eigen::Vector3d& p_previous = p_world_tag[previous];
    const double moved_m = (p_world_tag[k] - p_previous).norm();
    const double range_change_m = std::abs((p_world_tag[k] - p_world_anchor).norm() - (p_previous - p_world_anchor).norm());
    const double bias_m = travel_bias(difference_scale_m, std::max(moved_m - range_change_m, 0.0));
    squares += bias_m * bias_m;
    ++count;
  });
  return count > 0 ? std::sqrt(squares / static_cast<double>(count)) : travel_bias(difference_scale_m, 0.0);
}

CredibleTerms CredibleTermsOf(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                              std::span<const int> tag_id, const CovarianceOptions& options,
                              const TravelBias& travel_bias, const Eigen::Vector3d& p_world_anchor, double bias_m) {
  CredibleTerms terms;
  if (options.correlated_noise) terms.correlation_factor = CorrelationFactor(p_world_tag, range_m, p_world_anchor, bias_m);
  if (options.travel_bias && travel_bias) {
    terms.travel_bias_m = TravelBiasOf(p_world_tag, tag_id, p_world_anchor,
                                       DifferenceScale(p_world_tag, range_m, tag_id, p_world_anchor, bias_m), travel_bias);
  }
  return terms;
}

void MakeCredible(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m,
                  std::span<const int> tag_id, const CovarianceOptions& options, const TravelBias& travel_bias,
                  SolveResult* solve) {
  if (!Succeeded(solve->status) || !solve->covariance.allFinite()) return;
  MakeCredible(p_world_tag, tag_id, options,
               CredibleTermsOf(p_world_tag, range_m, tag_id, options, travel_bias, solve->p_world_anchor, solve->bias_m),
               solve);
}

void MakeCredible(std::span<const Eigen::Vector3d> p_world_tag, std::span<const int> tag_id,
                  const CovarianceOptions& options, const CredibleTerms& terms, SolveResult* solve) {
  if (!Succeeded(solve->status) || !solve->covariance.allFinite()) return;
  if (options.correlated_noise) {
    solve->covariance = ScaleRangeNoise(solve->covariance, solve->height_information, terms.correlation_factor);
  }
  solve->covariance +=
      ModelErrorCovariance(p_world_tag, tag_id, solve->p_world_anchor, options, terms.travel_bias_m, solve->height_weight);
}

Eigen::Matrix4d ScaleRangeNoise(const Eigen::Matrix4d& covariance, double height_information, double factor) {
  if (!(height_information > 0.0)) return factor * covariance;
  // In information form: the ranges' part P^-1 - Lambda scaled by 1 / factor, the prior's kept.
  Eigen::Matrix4d information;
  if (!internal::InvertNormalMatrix(covariance, &information)) return factor * covariance;
  information(2, 2) -= height_information;
  information /= factor;
  information(2, 2) += height_information;
  Eigen::Matrix4d scaled;
  if (!internal::InvertNormalMatrix(information, &scaled)) return factor * covariance;
  return scaled;
}

}  // namespace anchorbench::estimator
