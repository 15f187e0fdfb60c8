#include "anchorbench/report/run_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "anchorbench/io/format.hpp"
#include "anchorbench/report/why_not.hpp"
#include "anchorbench/report/paper_cells.hpp"

namespace anchorbench::report {
namespace {

using io::FormatFixed;
using io::FormatWithInterval;
using io::FormatNumber;
using io::FormatOptional;
using schema::Attempt;
using schema::RowConfig;

// The cells of a solve or an evaluation, empty where there is none.
std::optional<double> Of(const std::optional<Eigen::Vector3d>& v, int axis) {
  return v ? std::optional<double>((*v)[axis]) : std::nullopt;
}

void WriteOurTable(std::ostream& out, const std::vector<MethodSummary>& summaries, const std::vector<RowConfig>& rows,
                   const schema::ExperimentConfig& config) {
  std::string compared;
  for (const std::string& trigger : rows.front().estimator.triggers) compared += (compared.empty() ? "" : " vs ") + trigger;
  out << "# " << config.name << ": " << compared << "\n\n"
      << config.realizations << " realizations per row, seed " << config.seed
      << ". Errors over initialized attempts; Avg and Med [95% bootstrap interval over realizations], Ratio [95% "
         "Wilson interval]. "
      << kLatencyNote << "\n\n"
      << "| # | Method | Avg. (m) | Med. (m) | Init. | >1m | Ratio (%) | t_init mean / median (s) | Latency |\n"
      << "|---|---|---|---|---|---|---|---|---|\n";
  for (const MethodSummary& s : summaries) {
    out << "| " << rows[static_cast<std::size_t>(s.row)].name << " | " << s.method << " | "
        << FormatWithInterval(s.avg_m, s.avg_lo, s.avg_hi, 3) << " | " << FormatWithInterval(s.med_m, s.med_lo, s.med_hi, 3)
        << " | " << s.init << " / " << s.attempts << " | " << s.gt1m << " | "
        << FormatWithInterval(s.ratio_pct, s.ratio_lo, s.ratio_hi, 2) << " | "
        << (s.t_init_mean_s ? FormatFixed(*s.t_init_mean_s, 1) + " / " + FormatFixed(*s.t_init_med_s, 1) : "-") << " | "
        << LatencyCell(s) << " |\n";
  }
}

// "paper / ours (+x%)" of one cell, with the verdict against the +-25% target.
std::string Compare(const PaperCell& cell) {
  const int decimals = Decimals(cell.column);
  if (!cell.ours) return FormatFixed(cell.paper, decimals) + " / - ";
  const double relative = cell.paper != 0.0 ? (*cell.ours - cell.paper) / cell.paper : 0.0;
  std::ostringstream s;
  s << FormatFixed(cell.paper, decimals) << " / " << FormatFixed(*cell.ours, decimals) << " ("
    << (relative >= 0 ? "+" : "") << FormatFixed(100.0 * relative, 0) << "%)" << (WithinQuarter(cell) ? "" : " !");
  return s.str();
}

std::string Conclusions(const RowConfig& row, const MethodSummary& fixed, const MethodSummary& gated) {
  const bool avg_holds = gated.avg_m && fixed.avg_m && *gated.avg_m < *fixed.avg_m;
  const bool ratio_holds = gated.ratio_pct && fixed.ratio_pct && *gated.ratio_pct < *fixed.ratio_pct;
  return "- row " + row.name + ": gated Avg < fixed Avg: " + (avg_holds ? "yes" : "NO") +
         "; gated Ratio < fixed Ratio: " + (ratio_holds ? "yes" : "NO") + "\n";
}

const MethodSummary* Find(const std::vector<MethodSummary>& summaries, int row, const std::string& method) {
  for (const MethodSummary& s : summaries) {
    if (s.row == row && s.method == method) return &s;
  }
  return nullptr;
}

// One table line per method of the paper (paper / ours), scored by ScoreCells.
void WriteAgainstThePaper(std::ostream& out, const std::vector<MethodSummary>& summaries,
                          const std::vector<RowConfig>& rows) {
  out << "\n## Against the paper (paper / ours, relative difference; ! = outside +-25%)\n\n"
      << "| # | Method | Avg. (m) | Med. (m) | Init. | >1m | Ratio (%) |\n|---|---|---|---|---|---|---|\n";
  const std::vector<PaperCell> cells = CompareWithPaper(summaries, rows);
  std::string conclusions;
  for (std::size_t first = 0; first < cells.size(); first += std::size(kPaperColumns)) {
    const PaperCell& head = cells[first];
    out << "| " << rows[static_cast<std::size_t>(head.row)].name << " | " << head.method << " |";
    for (std::size_t c = 0; c < std::size(kPaperColumns); ++c) out << " " << Compare(cells[first + c]) << " |";
    out << "\n";
    if (head.method == schema::kPaperTrigger) {
      conclusions += Conclusions(rows[static_cast<std::size_t>(head.row)],
                                 *Find(summaries, head.row, schema::kFixedWindowTrigger),
                                 *Find(summaries, head.row, schema::kPaperTrigger));
    }
  }
  const PaperScore score = ScoreCells(cells);
  out << "\n" << score.within << " of " << score.cells
      << " target cells (Avg, Med, Init, Ratio; not the fixed window's Init, which matches by construction) within "
         "+-25%. The paper's value lies inside our 95% interval in "
      << score.inside_interval << " of " << score.with_interval << " Avg, Med and Ratio cells.\n\n"
      << "The paper's conclusions, row by row:\n" << conclusions;
}

void WriteAttemptLine(std::ostream& out, const Attempt& a, const std::vector<RowConfig>& rows) {
  const schema::AttemptEvaluation none;
  const schema::AttemptEvaluation& e = a.evaluation ? *a.evaluation : none;
  out << rows[static_cast<std::size_t>(a.row)].name << ',' << a.realization << ',' << a.anchor_id << ','
      << a.method << ',' << (a.initialized ? 1 : 0) << ',' << FormatOptional(a.t_init_s) << ',' << a.n_used << ','
      << FormatNumber(a.pdop_closest_point) << ','
      << (a.evaluation ? FormatNumber(e.pdop_true) : "") << ',' << FormatOptional(a.crlb_m) << ','
      << FormatOptional(e.error_m) << ',' << FormatOptional(Of(e.error_xyz_m, 0)) << ','
      << FormatOptional(Of(e.error_xyz_m, 1)) << ',' << FormatOptional(Of(e.error_xyz_m, 2)) << ','
      << FormatOptional(e.bias_error_m) << ',' << FormatOptional(a.solve ? std::optional(a.solve->alpha) : std::nullopt)
      << ',' << a.status << ',' << FormatOptional(e.bias_aware_dop) << ',' << FormatOptional(e.nees_position) << ','
      << FormatOptional(e.nees) << ',' << FormatOptional(e.bias_aware_hdop) << ','
      << FormatOptional(e.bias_aware_vdop) << ',' << WhyNotFields(a.why_not) << ',' << FormatOptional(e.t_first_s) << ','
      << FormatOptional(e.t_oracle_s) << ',' << FormatOptional(e.latency_ratio) << ',' << FormatOptional(e.t_ideal_s)
      << ',' << FormatOptional(e.ideal_latency_ratio);
}

}  // namespace

std::string AttemptLine(const Attempt& attempt, const std::vector<RowConfig>& rows) {
  std::ostringstream line;
  WriteAttemptLine(line, attempt, rows);
  return line.str();
}

void WriteAttempts(std::ostream& out, const std::vector<Attempt>& attempts, const std::vector<RowConfig>& rows) {
  out << kAttemptsColumns << '\n';
  for (const Attempt& a : attempts) {
    WriteAttemptLine(out, a, rows);
    out << '\n';
  }
}

void WriteAttemptLines(std::ostream& out, std::string_view lines) {
  out << kAttemptsColumns << '\n' << lines;
}

std::string LatencyCell(const MethodSummary& s) {
  if (!s.latency_med) return "-";
  return FormatFixed(*s.latency_med, 2) + "x (" + FormatFixed(*s.latency_p90, 2) + "x)";
}

std::string SummaryCsvFields(const MethodSummary& s, const std::vector<RowConfig>& rows) {
  std::ostringstream out;
  out << rows[static_cast<std::size_t>(s.row)].name << ',' << s.method << ',' << FormatOptional(s.avg_m) << ','
      << FormatOptional(s.med_m) << ',' << s.init << ',' << s.gt1m << ',' << FormatOptional(s.ratio_pct) << ','
      << FormatOptional(s.avg_lo) << ',' << FormatOptional(s.avg_hi) << ',' << FormatOptional(s.ratio_lo) << ','
      << FormatOptional(s.ratio_hi);
  const eval::Credibility& c = s.position_credibility;
  out << ',' << FormatOptional(c.anees) << ',' << FormatOptional(c.bound_lo) << ',' << FormatOptional(c.bound_hi) << ','
      << FormatOptional(c.above_95_pct) << ',' << FormatOptional(s.med_lo) << ',' << FormatOptional(s.med_hi) << ','
      << s.oracle_n << ',' << s.latency_n << ',' << FormatOptional(s.latency_med) << ',' << FormatOptional(s.latency_p90);
  return out.str();
}

void WriteSummaryCsv(std::ostream& out, const std::vector<MethodSummary>& summaries, const std::vector<RowConfig>& rows) {
  const bool with_paper = std::any_of(rows.begin(), rows.end(), [](const RowConfig& r) { return r.paper.has_value(); });
  out << kSummaryColumns << ",t_init_mean_s,t_init_med_s"
      << (with_paper ? ",paper_avg_m,paper_med_m,paper_init,paper_gt1m,paper_ratio_pct" : "") << '\n';
  for (const MethodSummary& s : summaries) {
    out << SummaryCsvFields(s, rows) << ',' << FormatOptional(s.t_init_mean_s) << ',' << FormatOptional(s.t_init_med_s);
    if (with_paper) {
      const std::optional<schema::PaperRow>& paper = rows[static_cast<std::size_t>(s.row)].paper;
      if (const schema::PaperCells* c = paper ? paper->For(s.method) : nullptr) {
        out << ',' << FormatNumber(c->avg_m) << ',' << FormatNumber(c->med_m) << ',' << FormatNumber(c->init) << ','
            << FormatNumber(c->gt1m) << ',' << FormatNumber(c->ratio_pct);
      } else {
        out << ",,,,,";
      }
    }
    out << '\n';
  }
}

void WriteSummaryMarkdown(std::ostream& out, const std::vector<MethodSummary>& summaries,
                          const std::vector<RowConfig>& rows, const schema::ExperimentConfig& config) {
  WriteOurTable(out, summaries, rows, config);
  if (std::any_of(rows.begin(), rows.end(), [](const RowConfig& r) { return r.paper.has_value(); })) {
    WriteAgainstThePaper(out, summaries, rows);
  }
}

std::string TimingCsvFields(const MethodSummary& s, const std::vector<RowConfig>& rows) {
  std::ostringstream out;
  out << rows[static_cast<std::size_t>(s.row)].name << ',' << s.method << ',' << s.attempts << ',' << s.init << ','
      << FormatFixed(s.compute_s, 6) << ',' << (s.attempts ? FormatFixed(1e6 * s.compute_s / s.attempts, 1) : "") << ','
      << (s.init ? FormatFixed(1e6 * s.compute_s / s.init, 1) : "");
  return out.str();
}

void WriteTimingCsv(std::ostream& out, const std::vector<MethodSummary>& summaries, const std::vector<RowConfig>& rows) {
  out << kTimingColumns << '\n';
  for (const MethodSummary& s : summaries) out << TimingCsvFields(s, rows) << '\n';
}

#ifdef __clang__
constexpr const char* kCompiler = "clang " __clang_version__;
#else
constexpr const char* kCompiler = "g++ " __VERSION__;
#endif
// Results are bit-identical across machines only within one of these (CMake's ANCHORBENCH_NATIVE).
#ifdef ANCHORBENCH_NATIVE_BUILD
constexpr const char* kInstructionSet = "native (-march=native: bytes differ from default builds)";
#else
constexpr const char* kInstructionSet = "default";
#endif

std::string ManifestJson(const schema::ExperimentConfig& config, const RunInfo& info) {
  nlohmann::ordered_json json;
  json["config_file"] = info.config_path;
  json["seed"] = config.seed;
  json["realizations"] = config.realizations;
  json["threads"] = info.threads;
  json["git_revision"] = info.revision;
  json["compiler"] = kCompiler;
  json["instruction_set"] = kInstructionSet;
  json["wall_time_s"] = std::round(info.wall_time_s * 1e3) / 1e3;  // ms: what a wall clock tells
  json["command_line"] = info.command_line;
  if (!info.sweep_axes.empty()) json["sweep_axes"] = info.sweep_axes;
  json["resolved_config"] = info.resolved_config;
  // Bytes that are not UTF-8 (a path, a log's line) become U+FFFD rather than an exception.
  return json.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace anchorbench::report
