#include "anchorbench/experiments/run_outputs.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "anchorbench/experiments/anchor_bank.hpp"
#include "anchorbench/experiments/csv_reader.hpp"

namespace anchorbench::experiments {
namespace {

std::string Optional(const std::optional<double>& value) { return value ? FormatNumber(*value) : ""; }

std::string JsonString(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

// YAML (as yaml-cpp holds it) to JSON: mappings, lists, numbers and booleans as such, text quoted.
std::string YamlToJson(const YAML::Node& node, int indent) {
  const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
  if (node.IsMap()) {
    std::string out = "{";
    bool first = true;
    for (const auto& entry : node) {
      out += (first ? "\n" : ",\n") + pad + JsonString(entry.first.as<std::string>()) + ": " +
             YamlToJson(entry.second, indent + 2);
      first = false;
    }
    return out + "\n" + std::string(static_cast<std::size_t>(indent), ' ') + "}";
  }
  if (node.IsSequence()) {
    std::string out = "[";
    for (std::size_t i = 0; i < node.size(); ++i) out += (i ? ",\n" : "\n") + pad + YamlToJson(node[i], indent + 2);
    return out + "\n" + std::string(static_cast<std::size_t>(indent), ' ') + "]";
  }
  const std::string scalar = node.Scalar();
  double number = 0.0;
  if (scalar == "true" || scalar == "false") return scalar;
  if (YAML::convert<double>::decode(node, number) && std::isfinite(number)) return FormatNumber(number);
  return JsonString(scalar);
}

std::string GitRevision() {
  std::string command = "git -C \"" + std::string(ANCHORBENCH_SOURCE_DIR) +
                        "\" describe --always --dirty --abbrev=12 2>/dev/null";
  std::array<char, 128> buffer{};
  std::string revision;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    while (fgets(buffer.data(), static_cast<int>(buffer.size()), pipe)) revision += buffer.data();
    pclose(pipe);
  }
  while (!revision.empty() && (revision.back() == '\n' || revision.back() == ' ')) revision.pop_back();
  return revision.empty() ? "unknown" : revision;
}

// "paper -> ours (+x%)" with the verdict against the +-25% target.
std::string Compare(double paper, const std::optional<double>& ours, int decimals, bool* within) {
  if (!ours) {
    *within = false;
    return FormatFixed(paper, decimals) + " / - ";
  }
  const double relative = paper != 0.0 ? (*ours - paper) / paper : 0.0;
  *within = std::abs(relative) <= 0.25 + 1e-12;
  std::ostringstream s;
  s << FormatFixed(paper, decimals) << " / " << FormatFixed(*ours, decimals) << " (" << (relative >= 0 ? "+" : "")
    << FormatFixed(100.0 * relative, 0) << "%)" << (*within ? "" : " !");
  return s.str();
}

}  // namespace

void WriteAttempts(std::ostream& out, const std::vector<Attempt>& attempts, const std::vector<RowConfig>& rows) {
  out << "row,realization,anchor_id,method,initialized,t_init,n_used,pdop_est,pdop_true,crlb_m,err_m,err_x,err_y,"
         "err_z,bias_err,alpha,status,bias_aware_dop\n";
  for (const Attempt& a : attempts) {
    const bool has_error = a.error_m.has_value();
    out << rows[static_cast<std::size_t>(a.row)].name << ',' << a.realization << ',' << a.anchor_id << ','
        << a.method << ',' << (a.initialized ? 1 : 0) << ',' << Optional(a.t_init_s) << ',' << a.n_used
        << ',' << FormatNumber(a.pdop_estimate) << ',' << Optional(a.pdop_true) << ',' << Optional(a.crlb_m) << ','
        << Optional(a.error_m) << ',' << (has_error ? FormatNumber(a.error_xyz_m.x()) : "") << ','
        << (has_error ? FormatNumber(a.error_xyz_m.y()) : "") << ','
        << (has_error ? FormatNumber(a.error_xyz_m.z()) : "") << ',' << Optional(a.bias_error_m) << ','
        << Optional(a.alpha) << ',' << a.status << ',' << Optional(a.bias_aware_dop) << '\n';
  }
}

std::string SummaryCsvFields(const MethodSummary& s, const std::vector<RowConfig>& rows) {
  std::ostringstream out;
  out << rows[static_cast<std::size_t>(s.row)].name << ',' << s.method << ',' << Optional(s.avg_m) << ','
      << Optional(s.med_m) << ',' << s.init << ',' << s.gt1m << ',' << Optional(s.ratio_pct) << ','
      << Optional(s.avg_lo) << ',' << Optional(s.avg_hi) << ',' << Optional(s.ratio_lo) << ',' << Optional(s.ratio_hi);
  return out.str();
}

void WriteSummaryCsv(std::ostream& out, const std::vector<MethodSummary>& summaries, const std::vector<RowConfig>& rows) {
  // Where rows carry the paper's values, they follow the documented columns (for plots).
  const bool with_paper = std::any_of(rows.begin(), rows.end(), [](const RowConfig& r) { return r.paper.has_value(); });
  out << kSummaryColumns << ",t_init_mean_s,t_init_med_s"
      << (with_paper ? ",paper_avg_m,paper_med_m,paper_init,paper_gt1m,paper_ratio_pct" : "") << '\n';
  for (const MethodSummary& s : summaries) {
    out << SummaryCsvFields(s, rows) << ',' << Optional(s.t_init_mean_s) << ',' << Optional(s.t_init_med_s);
    if (with_paper) {
      const std::optional<PaperRow>& paper = rows[static_cast<std::size_t>(s.row)].paper;
      if (const PaperCells* c = paper ? paper->For(s.method) : nullptr) {
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
                          const std::vector<RowConfig>& rows, const ExperimentConfig& config) {
  std::string compared;
  for (const std::string& trigger : rows.front().estimator.triggers) compared += (compared.empty() ? "" : " vs ") + trigger;
  out << "# " << config.name << ": " << compared << "\n\n"
      << config.realizations << " realizations per row, seed " << config.seed
      << ". Errors over initialized attempts; [95% bootstrap interval over realizations].\n\n"
      << "| # | Method | Avg. (m) | Med. (m) | Init. | >1m | Ratio (%) | t_init mean / median (s) |\n"
      << "|---|---|---|---|---|---|---|---|\n";
  auto interval = [](const std::optional<double>& lo, const std::optional<double>& hi, int decimals) {
    return lo ? " [" + FormatFixed(*lo, decimals) + ", " + FormatFixed(*hi, decimals) + "]" : std::string();
  };
  for (const MethodSummary& s : summaries) {
    out << "| " << rows[static_cast<std::size_t>(s.row)].name << " | " << s.method << " | "
        << (s.avg_m ? FormatFixed(*s.avg_m, 3) + interval(s.avg_lo, s.avg_hi, 3) : "-") << " | "
        << (s.med_m ? FormatFixed(*s.med_m, 3) : "-") << " | " << s.init << " / " << s.attempts << " | " << s.gt1m << " | "
        << (s.ratio_pct ? FormatFixed(*s.ratio_pct, 2) + interval(s.ratio_lo, s.ratio_hi, 2) : "-") << " | "
        << (s.t_init_mean_s ? FormatFixed(*s.t_init_mean_s, 1) + " / " + FormatFixed(*s.t_init_med_s, 1) : "-") << " |\n";
  }

  bool any_paper = false;
  for (const RowConfig& row : rows) any_paper |= row.paper.has_value();
  if (!any_paper) return;
  out << "\n## Against the paper (paper / ours, relative difference; ! = outside +-25%)\n\n"
      << "| # | Method | Avg. (m) | Med. (m) | Init. | >1m | Ratio (%) |\n|---|---|---|---|---|---|---|\n";
  int cells = 0, within_count = 0;
  std::string conclusions;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (!rows[r].paper) continue;
    // The paper's two methods, if this row ran both.
    const MethodSummary* by_method[2] = {nullptr, nullptr};
    for (const MethodSummary& s : summaries) {
      if (s.row != static_cast<int>(r)) continue;
      if (s.method == kFixedWindowTrigger) by_method[0] = &s;
      if (s.method == kPaperTrigger) by_method[1] = &s;
    }
    if (!by_method[0] || !by_method[1]) continue;
    for (int m = 0; m < 2; ++m) {
      const MethodSummary& s = *by_method[m];
      const PaperCells& paper = *rows[r].paper->For(s.method);
      bool within[5];
      out << "| " << rows[r].name << " | " << s.method << " | "
          << Compare(paper.avg_m, s.avg_m, 3, &within[0]) << " | " << Compare(paper.med_m, s.med_m, 3, &within[1])
          << " | " << Compare(paper.init, static_cast<double>(s.init), 0, &within[2]) << " | "
          << Compare(paper.gt1m, static_cast<double>(s.gt1m), 0, &within[3]) << " | "
          << Compare(paper.ratio_pct, s.ratio_pct, 2, &within[4]) << " |\n";
      // >1m is a count that follows from Init and Ratio; the targets are the other four cells.
      for (int c : {0, 1, 2, 4}) {
        ++cells;
        within_count += within[c];
      }
    }
    const MethodSummary& fixed = *by_method[0];
    const MethodSummary& gated = *by_method[1];
    const bool avg_holds = gated.avg_m && fixed.avg_m && *gated.avg_m < *fixed.avg_m;
    const bool ratio_holds = gated.ratio_pct && fixed.ratio_pct && *gated.ratio_pct < *fixed.ratio_pct;
    conclusions += "- row " + rows[r].name + ": gated Avg < fixed Avg: " + (avg_holds ? "yes" : "NO") +
                   "; gated Ratio < fixed Ratio: " + (ratio_holds ? "yes" : "NO") + "\n";
  }
  out << "\n" << within_count << " of " << cells << " target cells (Avg, Med, Init, Ratio) within +-25%.\n\n"
      << "The paper's conclusions, row by row:\n" << conclusions;
}

std::string TimingCsvFields(const MethodSummary& s, const std::vector<RowConfig>& rows) {
  std::ostringstream out;
  out << rows[static_cast<std::size_t>(s.row)].name << ',' << s.method << ',' << s.attempts << ',' << s.init << ','
      << FormatFixed(s.compute_s, 6) << ',' << (s.attempts ? FormatFixed(1e6 * s.compute_s / s.attempts, 1) : "") << ','
      << (s.init ? FormatFixed(1e6 * s.compute_s / s.init, 1) : "");
  return out.str();
}

std::string ManifestJson(const ExperimentConfig& config, const RunInfo& info) {
  std::ostringstream json;
  json << "{\n  \"config_file\": " << JsonString(info.config_path) << ",\n  \"seed\": " << config.seed
       << ",\n  \"realizations\": " << config.realizations << ",\n  \"threads\": " << info.threads
       << ",\n  \"git_revision\": " << JsonString(GitRevision()) << ",\n  \"compiler\": "
       << JsonString(std::string("g++ ") + __VERSION__) << ",\n  \"wall_time_s\": " << FormatFixed(info.wall_time_s, 3)
       << ",\n  \"resolved_config\": " << YamlToJson(YAML::Load(ToYaml(config)), 2) << "\n}\n";
  return json.str();
}

}  // namespace anchorbench::experiments
