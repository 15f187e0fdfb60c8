// exploration.hpp's files: an exploration study's records as CSV and Markdown tables.
#include "anchorbench/studies/exploration.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <utility>
#include <sstream>

#include "anchorbench/report/navigation_report.hpp"
#include "anchorbench/report/run_outputs.hpp"

namespace anchorbench::studies {

using engine::FileWriter;
namespace {


struct PolicySummary {
  int row = 0;
  std::string policy;
  int runs = 0, all_certified = 0, anchors = 0, certified = 0, beyond_accuracy = 0;
  double median_t_all_s = std::numeric_limits<double>::infinity();  // over the runs, a run not all certified counting as +inf
  // Paired by realization (the same anchors, pattern and link noise): the median of this policy's
  // time over the pattern's, over the realizations the pattern certifies whole (a run of this
  // policy that does not counts +inf); NaN for the pattern itself or without such a realization.
  double median_ratio_to_pattern = std::numeric_limits<double>::quiet_NaN();
  double max_error_m = 0.0, mean_distance_m = 0.0, mean_detours = 0.0;
  double mean_navigation_rmse_m = -1.0;  // -1: not navigated
};

double Median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::infinity();
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The pattern's time to certify every anchor, by (row, realization), where it does.
std::map<std::pair<int, int>, double> PatternTimes(const std::vector<ExplorationRecord>& records) {
  std::map<std::pair<int, int>, double> t_pattern_s;
  for (const ExplorationRecord& r : records) {
    if (r.policy == schema::kPatternPolicy && r.t_all_certified_s > 0.0) t_pattern_s[{r.row, r.realization}] = r.t_all_certified_s;
  }
  return t_pattern_s;
}

std::vector<PolicySummary> Summarize(const std::vector<ExplorationRecord>& records, const schema::ExplorationConfig& ex,
                                     int rows) {
  const std::map<std::pair<int, int>, double> t_pattern_s = PatternTimes(records);
  std::vector<PolicySummary> summaries;
  for (int row = 0; row < rows; ++row) {
    for (const std::string& policy : ex.policies) {
      PolicySummary s;
      s.row = row;
      s.policy = policy;
      std::vector<double> t_all, to_pattern;
      double rmse_sum_m = 0.0;
      int navigated = 0;
      for (const ExplorationRecord& r : records) {
        if (r.row != row || r.policy != policy) continue;
        ++s.runs;
        s.anchors += r.anchors;
        s.certified += r.certified;
        s.beyond_accuracy += r.beyond_accuracy;
        s.max_error_m = std::max(s.max_error_m, r.max_error_m);
        s.mean_distance_m += r.distance_m;
        s.mean_detours += r.detours;
        if (r.t_all_certified_s >= 0.0) ++s.all_certified;
        if (r.navigation_rmse_m >= 0.0) {
          rmse_sum_m += r.navigation_rmse_m;
          ++navigated;
        }
        t_all.push_back(r.t_all_certified_s >= 0.0 ? r.t_all_certified_s : std::numeric_limits<double>::infinity());
        const auto pattern = t_pattern_s.find({r.row, r.realization});
        if (policy != schema::kPatternPolicy && pattern != t_pattern_s.end()) to_pattern.push_back(t_all.back() / pattern->second);
      }
      if (s.runs > 0) {
        s.mean_distance_m /= s.runs;
        s.mean_detours /= s.runs;
      }
      if (navigated > 0) s.mean_navigation_rmse_m = rmse_sum_m / navigated;
      s.median_t_all_s = Median(t_all);
      if (!to_pattern.empty()) s.median_ratio_to_pattern = Median(to_pattern);
      summaries.push_back(s);
    }
  }
  return summaries;
}

std::string Fixed(double value, int digits) {
  if (!std::isfinite(value)) return "inf";
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << value;
  return out.str();
}

}  // namespace

std::string WriteExplorationFiles(const FileWriter& write, const schema::ExperimentConfig& config,
                                  const std::vector<ExplorationRecord>& records, const report::RunInfo& info) {
  const std::vector<schema::RowConfig> rows = schema::RowsOf(config);
  write("exploration.csv", [&](std::ostream& file) {
    file << "row,realization,policy,anchors,certified,beyond_accuracy,max_error_m,t_all_certified_s,duration_s,"
            "distance_m,detours,navigation_rmse_m\n";
    for (const ExplorationRecord& r : records) {
      file << rows[static_cast<std::size_t>(r.row)].name << ',' << r.realization << ',' << r.policy << ',' << r.anchors << ','
           << r.certified << ',' << r.beyond_accuracy << ',' << Fixed(r.max_error_m, 4) << ','
           << (r.t_all_certified_s >= 0.0 ? Fixed(r.t_all_certified_s, 1) : "") << ',' << Fixed(r.duration_s, 1) << ','
           << Fixed(r.distance_m, 2) << ',' << r.detours << ','
           << (r.navigation_rmse_m >= 0.0 ? Fixed(r.navigation_rmse_m, 4) : "") << '\n';
    }
  });
  const std::vector<PolicySummary> summaries = Summarize(records, *config.exploration, static_cast<int>(rows.size()));
  write("exploration_summary.csv", [&](std::ostream& file) {
    file << "row,policy,runs,all_certified_runs,median_t_all_certified_s,anchors,certified,beyond_accuracy,"
            "median_ratio_to_pattern,max_error_m,mean_distance_m,mean_detours,mean_navigation_rmse_m\n";
    for (const PolicySummary& s : summaries) {
      file << rows[static_cast<std::size_t>(s.row)].name << ',' << s.policy << ',' << s.runs << ',' << s.all_certified << ','
           << Fixed(s.median_t_all_s, 1) << ',' << s.anchors << ',' << s.certified << ',' << s.beyond_accuracy << ','
           << (std::isnan(s.median_ratio_to_pattern) ? "" : Fixed(s.median_ratio_to_pattern, 3)) << ','
           << Fixed(s.max_error_m, 3) << ',' << Fixed(s.mean_distance_m, 1) << ',' << Fixed(s.mean_detours, 1) << ','
           << (s.mean_navigation_rmse_m >= 0.0 ? Fixed(s.mean_navigation_rmse_m, 3) : "") << '\n';
    }
  });
  std::ostringstream md;
  md << "# " << config.name << ": closed-loop exploration\n\n"
     << "Time until every anchor is certified (trigger `" << config.exploration->trigger << "`, D = "
     << Fixed(rows.front().estimator.certificate.accuracy_m, 2) << " m), per policy; a run that ends at "
     << Fixed(config.exploration->max_duration_s, 0) << " s with an anchor waiting counts as inf in the median.\n\n"
     << "| row | policy | runs all certified | median time to certify all (s) | median time over the pattern's (paired) | "
        "anchors certified | beyond D | max error (m) | mean distance (m) | mean detours | mean navigation RMSE (m) |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const PolicySummary& s : summaries) {
    md << "| " << rows[static_cast<std::size_t>(s.row)].name << " | " << s.policy << " | " << s.all_certified << " / "
       << s.runs << " | " << Fixed(s.median_t_all_s, 1) << " | "
       << (std::isnan(s.median_ratio_to_pattern) ? "-" : Fixed(s.median_ratio_to_pattern, 2) + "x") << " | " << s.certified << " / " << s.anchors << " | "
       << s.beyond_accuracy << " | " << Fixed(s.max_error_m, 2) << " | " << Fixed(s.mean_distance_m, 0) << " | "
       << Fixed(s.mean_detours, 1) << " | "
       << (s.mean_navigation_rmse_m >= 0.0 ? Fixed(s.mean_navigation_rmse_m, 3) : "-") << " |\n";
  }
  write("exploration.md", [&](std::ostream& file) { file << md.str(); });
  if (config.navigation) {
    std::vector<nav::NavigationRecord> navigated;
    for (const ExplorationRecord& r : records) {
      nav::NavigationRecord n{r.row, r.realization, r.policy, {}};
      n.outcome.error_by_bin_m = r.navigation_error_by_bin_m;
      navigated.push_back(std::move(n));
    }
    write("navigation_error.csv", [&](std::ostream& file) {
      report::WriteNavigationErrorCsv(file, navigated, rows, config.navigation->error_bin_s);
    });
  }
  write("manifest.json", [&](std::ostream& file) { file << report::ManifestJson(config, info); });
  return md.str();
}

}  // namespace anchorbench::studies
