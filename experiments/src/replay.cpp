#include "anchorbench/experiments/replay.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "anchorbench/experiments/csv_reader.hpp"

namespace anchorbench::experiments {
namespace {

std::string Optional(const std::optional<double>& value) { return value ? FormatNumber(*value) : ""; }

// The columns of estimates.csv for one outcome, as text (empty where not applicable).
std::vector<std::string> EstimateFields(const AttemptOutcome& o) {
  const bool has_estimate = o.initialized && o.solve;
  const Eigen::Vector3d p = has_estimate ? o.solve->p_world_anchor : Eigen::Vector3d::Zero();
  return {std::to_string(o.anchor_id),
          o.method,
          o.initialized ? "1" : "0",
          Optional(o.t_init_s),
          std::to_string(o.n_used),
          FormatNumber(o.pdop_estimate),
          Optional(o.pdop_true),
          has_estimate ? FormatNumber(p.x()) : "",
          has_estimate ? FormatNumber(p.y()) : "",
          has_estimate ? FormatNumber(p.z()) : "",
          has_estimate ? FormatNumber(o.solve->bias_m) : "",
          Optional(o.error_m)};
}

constexpr const char* kEstimateColumns[] = {"anchor_id", "method", "initialized", "t_init", "n_used", "pdop_est",
                                            "pdop_true", "x", "y", "z", "bias", "err_m"};

}  // namespace

ReplayResult Replay(const PoseTracks& poses, const std::vector<RangeRecord>& ranges,
                    const std::map<int, AnchorTruth>* truth, const estimator::InitializerOptions& options,
                    const TraceSink& trace, std::uint64_t seed) {
  ReplayResult result;
  std::vector<estimator::RangeSample> samples;
  std::vector<const RangeRecord*> records;  // the record of each sample, for the trace
  for (const RangeRecord& range : ranges) {
    const std::optional<Eigen::Vector3d> p_world_tag = poses.At(range.tag_id, range.t_s);
    if (!p_world_tag) {
      if (result.ranges_skipped++ == 0) result.first_skipped_line = range.line;
      continue;
    }
    samples.push_back({range.t_s, range.tag_id, range.anchor_id, range.range_m, *p_world_tag});
    records.push_back(&range);
  }
  result.ranges_used = static_cast<int>(samples.size());
  const double t_end_s = samples.empty() ? 0.0 : samples.back().t_s;
  AnchorBank bank(options, seed, 0, truth);
  AnchorBank::Trace each;
  if (trace) each = [&](std::size_t i, const estimator::FeedResult& fed) { trace(*records[i], fed); };
  result.outcomes = bank.Run(samples, t_end_s, each);
  return result;
}

void CheckReplayable(const std::vector<RangeRecord>& ranges, const std::map<int, AnchorTruth>* truth,
                     const estimator::InitializerOptions& options) {
  AnchorBank bank(options, 0, 0, truth);
  for (const RangeRecord& range : ranges) bank.AddAnchor(range.anchor_id);
}

void WriteEstimates(std::ostream& out, const std::vector<AttemptOutcome>& outcomes) {
  for (std::size_t i = 0; i < std::size(kEstimateColumns); ++i) out << (i ? "," : "") << kEstimateColumns[i];
  out << '\n';
  for (const AttemptOutcome& o : outcomes) {
    const std::vector<std::string> fields = EstimateFields(o);
    for (std::size_t i = 0; i < fields.size(); ++i) out << (i ? "," : "") << fields[i];
    out << '\n';
  }
}

void PrintEstimates(std::ostream& out, const std::vector<AttemptOutcome>& outcomes) {
  constexpr int kWidth[] = {10, 20, 12, 10, 8, 10, 10, 10, 10, 10, 10, 10};
  for (std::size_t i = 0; i < std::size(kEstimateColumns); ++i) out << std::setw(kWidth[i]) << kEstimateColumns[i];
  out << '\n';
  for (const AttemptOutcome& o : outcomes) {
    std::vector<std::string> fields = EstimateFields(o);
    // Terminal view: three decimals instead of the lossless CSV text.
    const std::optional<double> numbers[] = {o.t_init_s, o.pdop_estimate, o.pdop_true};
    const int columns[] = {3, 5, 6};
    for (int k = 0; k < 3; ++k)
      if (numbers[k] && std::isfinite(*numbers[k])) fields[columns[k]] = FormatFixed(*numbers[k], 3);
    if (o.initialized && o.solve) {
      for (int k = 0; k < 3; ++k) fields[7 + k] = FormatFixed(o.solve->p_world_anchor[k], 3);
      fields[10] = FormatFixed(o.solve->bias_m, 3);
    }
    if (o.error_m) fields[11] = FormatFixed(*o.error_m, 3);
    for (std::size_t i = 0; i < fields.size(); ++i) out << std::setw(kWidth[i]) << (fields[i].empty() ? "-" : fields[i]);
    out << '\n';
  }
}

void WriteTraceRow(std::ostream& out, const RangeRecord& range, const estimator::FeedResult& fed) {
  out << FormatNumber(range.t_s) << ',' << range.tag_id << ',' << range.anchor_id << ',' << FormatNumber(range.range_m)
      << ',' << (fed.accepted ? 1 : 0) << ',' << fed.n_accepted << ',' << FormatNumber(fed.pdop) << '\n';
}

}  // namespace anchorbench::experiments
