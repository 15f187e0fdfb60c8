#include "anchorbench/report/sweep_report.hpp"

#include "anchorbench/io/format.hpp"
#include "anchorbench/report/run_outputs.hpp"

namespace anchorbench::report {
namespace {

// Every (point, summary) line: the point's values, then `fields` of the summary.
template <typename Fields>
void WriteLines(std::ostream& out, const std::vector<SweepPointResult>& results, Fields fields) {
  for (const SweepPointResult& result : results) {
    for (const MethodSummary& s : result.summaries) {
      for (const std::string& value : result.point.values) out << value << ',';
      out << fields(s, result.rows) << '\n';
    }
  }
}

void WriteKeys(std::ostream& out, const std::vector<schema::SweepAxis>& axes) {
  for (const schema::SweepAxis& axis : axes) out << axis.key << ',';
}

}  // namespace

void WriteSweepCsv(std::ostream& out, const std::vector<schema::SweepAxis>& axes,
                   const std::vector<SweepPointResult>& results) {
  WriteKeys(out, axes);
  out << kSummaryColumns << '\n';
  WriteLines(out, results, SummaryCsvFields);
}

void WriteSweepTiming(std::ostream& out, const std::vector<schema::SweepAxis>& axes,
                      const std::vector<SweepPointResult>& results) {
  WriteKeys(out, axes);
  out << kTimingColumns << '\n';
  WriteLines(out, results, TimingCsvFields);
}

void WriteSweepMarkdown(std::ostream& out, const std::string& name, int realizations, std::uint64_t seed,
                        const std::vector<schema::SweepAxis>& axes, const std::vector<SweepPointResult>& results) {
  out << "# " << name << ": sweep\n\n" << realizations << " realizations per point and row, seed " << seed << ". "
      << kLatencyNote << "\n\n|";
  for (const schema::SweepAxis& axis : axes) out << ' ' << axis.key << " |";
  out << " Row | Method | Avg. (m) | Med. (m) | Init. | >1m | Ratio (%) | Latency |\n|";
  for (std::size_t a = 0; a < axes.size() + 8; ++a) out << "---|";
  out << '\n';
  for (const SweepPointResult& result : results) {
    for (const MethodSummary& s : result.summaries) {
      out << '|';
      for (const std::string& value : result.point.values) out << ' ' << value << " |";
      out << ' ' << result.rows[static_cast<std::size_t>(s.row)].name << " | " << s.method << " | " << io::FormatFixed(s.avg_m, 3)
          << " | " << io::FormatFixed(s.med_m, 3) << " | " << s.init << " | " << s.gt1m << " | " << io::FormatFixed(s.ratio_pct, 2) << " | " << LatencyCell(s) << " |\n";
    }
  }
}

}  // namespace anchorbench::report
