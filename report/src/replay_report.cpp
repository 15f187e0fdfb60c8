#include "anchorbench/report/replay_report.hpp"

#include <cmath>
#include <iomanip>
#include <optional>
#include <string>

#include <Eigen/Eigenvalues>

#include "anchorbench/estimator/certified_trigger.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/report/why_not.hpp"

namespace anchorbench::report {
namespace {

using io::FormatFixed;
using io::FormatNumber;
using io::FormatOptional;

constexpr const char* kEstimateColumns[] = {"anchor_id", "method", "initialized", "t_init", "n_used", "pdop_est",
                                            "pdop_true", "x", "y", "z", "bias", "err_m", "status", "err_xy", "err_z",
                                            "bias_aware_hdop", "bias_aware_vdop", "scale", "blocked_by",
                                            "blocked_value", "blocked_limit", "samples_needed", "evidence_explained",
                                            "t_first", "t_oracle", "latency", "radius99_m"};

// The radius of the estimate's 99% position region: sqrt(chi2_3(0.99) lambda_max) of its covariance.
std::string Radius99(const schema::Attempt& a) {
  if (!a.initialized || !a.solve) return "";
  const Eigen::Matrix3d position = a.solve->covariance.topLeftCorner<3, 3>();
  if (!position.allFinite() || position.isZero()) return "";
  const double largest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(position, Eigen::EigenvaluesOnly).eigenvalues()(2);
  return FormatNumber(std::sqrt(estimator::ChiSquare3Quantile(0.99) * std::max(largest, 0.0)));
}

// Three decimals for a terminal, or the shortest text where that would be a wall of digits.
std::string ForTerminal(double value) { return std::abs(value) < 1e9 ? FormatFixed(value, 3) : FormatNumber(value); }

// The horizontal and the vertical part of an initialized attempt's error, where the truth is known.
std::optional<double> ErrorXy(const schema::Attempt& a) {
  if (!a.evaluation || !a.evaluation->error_xyz_m) return std::nullopt;
  return a.evaluation->error_xyz_m->head<2>().norm();
}
std::optional<double> ErrorZ(const schema::Attempt& a) {
  if (!a.evaluation || !a.evaluation->error_xyz_m) return std::nullopt;
  return std::abs(a.evaluation->error_xyz_m->z());
}

// One of WhyNotFields' three cells.
std::string WhyNotCell(const schema::Attempt& a, int cell) {
  const std::string fields = WhyNotFields(a.why_not);
  std::size_t start = 0;
  for (int c = 0; c < cell; ++c) start = fields.find(',', start) + 1;
  return fields.substr(start, fields.find(',', start) - start);
}

// The columns of estimates.csv for one attempt, as text (empty where not applicable).
std::vector<std::string> EstimateFields(const schema::Attempt& a) {
  const bool has_estimate = a.initialized && a.solve;
  const Eigen::Vector3d p = has_estimate ? a.solve->p_world_anchor : Eigen::Vector3d::Zero();
  return {std::to_string(a.anchor_id),
          a.method,
          a.initialized ? "1" : "0",
          FormatOptional(a.t_init_s),
          has_estimate ? std::to_string(a.n_used) : "",  // nothing estimated: nothing used (blocked_* say why)
          has_estimate ? FormatNumber(a.pdop_closest_point) : "",
          a.evaluation ? FormatNumber(a.evaluation->pdop_true) : "",
          has_estimate ? FormatNumber(p.x()) : "",
          has_estimate ? FormatNumber(p.y()) : "",
          has_estimate ? FormatNumber(p.z()) : "",
          has_estimate ? FormatNumber(a.solve->bias_m) : "",
          a.evaluation ? FormatOptional(a.evaluation->error_m) : "",
          a.status,
          ErrorXy(a) ? FormatNumber(*ErrorXy(a)) : "",
          ErrorZ(a) ? FormatNumber(*ErrorZ(a)) : "",
          a.evaluation ? FormatOptional(a.evaluation->bias_aware_hdop) : "",
          a.evaluation ? FormatOptional(a.evaluation->bias_aware_vdop) : "",
          has_estimate && a.solve->range_scale_sigma > 0.0 ? FormatNumber(a.solve->range_scale) : "",
          // why it waits: three fields, split here into three cells
          WhyNotCell(a, 0), WhyNotCell(a, 1), WhyNotCell(a, 2),
          a.why_not && !std::isnan(a.why_not->samples_needed) ? FormatNumber(a.why_not->samples_needed) : "",
          a.why_not && !std::isnan(a.why_not->evidence_explained) ? FormatNumber(a.why_not->evidence_explained) : "",
          a.evaluation ? FormatOptional(a.evaluation->t_first_s) : "",
          a.evaluation ? FormatOptional(a.evaluation->t_oracle_s) : "",
          a.evaluation ? FormatOptional(a.evaluation->latency_ratio) : "",
          Radius99(a)};
}

}  // namespace

void WriteEstimates(std::ostream& out, const std::vector<schema::Attempt>& attempts) {
  for (std::size_t i = 0; i < std::size(kEstimateColumns); ++i) out << (i ? "," : "") << kEstimateColumns[i];
  out << '\n';
  for (const schema::Attempt& a : attempts) {
    const std::vector<std::string> fields = EstimateFields(a);
    for (std::size_t i = 0; i < fields.size(); ++i) out << (i ? "," : "") << fields[i];
    out << '\n';
  }
}

void PrintEstimates(std::ostream& out, const std::vector<schema::Attempt>& attempts) {
  // The terminal shows the columns up to err_z; the DOP split is in estimates.csv.
  static constexpr int kWidth[] = {10, 20, 12, 10, 8, 10, 10, 10, 10, 10, 10, 10, 21, 10, 10};
  static_assert(std::size(kWidth) <= std::size(kEstimateColumns));
  // Each cell right-aligned in its width less one, after one space: a wider value (an epoch time)
  // pushes the row right but never runs into its neighbour.
  const auto cell = [&out](std::size_t i, const std::string& text) {
    if (i > 0) out << ' ';
    out << std::setw(kWidth[i] - 1) << text;
  };
  for (std::size_t i = 0; i < std::size(kWidth); ++i) cell(i, kEstimateColumns[i]);
  out << '\n';
  for (const schema::Attempt& a : attempts) {
    std::vector<std::string> fields = EstimateFields(a);
    // Terminal view: three decimals instead of the lossless CSV text.
    const std::optional<double> pdop_true = a.evaluation ? std::optional(a.evaluation->pdop_true) : std::nullopt;
    const std::optional<double> pdop_est =
        a.initialized && a.solve ? std::optional(a.pdop_closest_point) : std::nullopt;  // as in the CSV
    const std::optional<double> numbers[] = {a.t_init_s, pdop_est, pdop_true};
    const int columns[] = {3, 5, 6};
    for (int k = 0; k < 3; ++k)
      if (numbers[k] && std::isfinite(*numbers[k])) fields[columns[k]] = ForTerminal(*numbers[k]);
    if (a.initialized && a.solve) {
      for (int k = 0; k < 3; ++k) fields[7 + k] = ForTerminal(a.solve->p_world_anchor[k]);
      fields[10] = ForTerminal(a.solve->bias_m);
    }
    if (a.evaluation && a.evaluation->error_m) fields[11] = ForTerminal(*a.evaluation->error_m);
    if (ErrorXy(a)) fields[13] = ForTerminal(*ErrorXy(a));
    if (ErrorZ(a)) fields[14] = ForTerminal(*ErrorZ(a));
    for (std::size_t i = 0; i < std::size(kWidth); ++i) cell(i, fields[i].empty() ? "-" : fields[i]);
    out << '\n';
  }
}

void WriteTraceRow(std::ostream& out, const io::RangeRecord& range, const estimator::FeedResult& fed) {
  out << FormatNumber(range.t_s) << ',' << range.tag_id << ',' << range.anchor_id << ',' << FormatNumber(range.range_m)
      << ',' << (fed.accepted ? 1 : 0) << ',' << fed.n_accepted << ',' << FormatNumber(fed.pdop) << '\n';
}

}  // namespace anchorbench::report
