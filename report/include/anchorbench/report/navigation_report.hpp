#pragma once
// The navigation study's files (anchorbench navigate; docs/navigation.md):
//   navigation.csv          one line per (row, realization, method);
//   navigation_summary.csv  per (row, method): the mean position RMSE with its 95% interval (a
//                           bootstrap over realizations, as Table I's), the median end error, the
//                           mean share of time with a fix, and when anchors came;
//   navigation_error.csv    per (row, method, time bin): the position error over time, its mean
//                           and 90th percentile over realizations (the figure's data);
//   navigation.md           the same for people.

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "anchorbench/nav/navigate.hpp"
#include "anchorbench/schema/experiment.hpp"

namespace anchorbench::report {

struct NavigationSummary {
  int row = 0;
  std::string method;
  int runs = 0;
  double rmse_mean_m = 0.0;
  std::optional<double> rmse_lo_m, rmse_hi_m;  // none without resamples
  double final_error_median_m = 0.0;
  double fix_share_mean = 0.0;
  int with_first_anchor = 0;                   // runs where any anchor came
  std::optional<double> t_first_anchor_median_s, t_kth_anchor_median_s;
  // Runs whose RMSE is above the drift's (odometry alone) in the same realization: where the
  // anchors made navigation worse than using none. None for the drift itself.
  std::optional<int> worse_than_drift;
};

// Per row and method in the records' order; the bootstrap draws from (seed, row,
// kBootstrapStream, a hash of "navigation:" and the method). `drift_method` names the records of
// odometry alone, the pairs worse_than_drift compares with.
std::vector<NavigationSummary> SummarizeNavigation(const std::vector<nav::NavigationRecord>& records, int rows,
                                                   int resamples, std::uint64_t seed, const std::string& drift_method);

void WriteNavigationErrorCsv(std::ostream& out, const std::vector<nav::NavigationRecord>& records,
                             const std::vector<schema::RowConfig>& rows, double error_bin_s);

void WriteNavigationCsv(std::ostream& out, const std::vector<nav::NavigationRecord>& records,
                        const std::vector<schema::RowConfig>& rows);
void WriteNavigationSummaryCsv(std::ostream& out, const std::vector<NavigationSummary>& summaries,
                               const std::vector<schema::RowConfig>& rows);
void WriteNavigationMarkdown(std::ostream& out, const std::vector<NavigationSummary>& summaries,
                             const std::vector<schema::RowConfig>& rows, const schema::ExperimentConfig& config);

}  // namespace anchorbench::report
