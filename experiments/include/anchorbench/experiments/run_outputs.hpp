#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "anchorbench/experiments/config.hpp"
#include "anchorbench/experiments/monte_carlo.hpp"
#include "anchorbench/experiments/summary.hpp"

namespace anchorbench::experiments {

// attempts.csv: one row per attempt, columns
// row,realization,anchor_id,method,initialized,t_init,n_used,pdop_est,pdop_true,crlb_m,err_m,
// err_x,err_y,err_z,bias_err,alpha,status,bias_aware_dop (empty where not applicable; never NaN).
void WriteAttempts(std::ostream& out, const std::vector<Attempt>& attempts, const std::vector<RowConfig>& rows);

// summary.csv: row,method,avg_m,med_m,init,gt1m,ratio_pct,avg_lo,avg_hi,ratio_lo,ratio_hi
constexpr const char* kSummaryColumns = "row,method,avg_m,med_m,init,gt1m,ratio_pct,avg_lo,avg_hi,ratio_lo,ratio_hi";
std::string SummaryCsvFields(const MethodSummary& summary, const std::vector<RowConfig>& rows);
void WriteSummaryCsv(std::ostream& out, const std::vector<MethodSummary>& summaries, const std::vector<RowConfig>& rows);

// summary.md: our table, and where rows carry the paper's values, the two side by side cell by
// cell with the relative difference, and whether the paper's conclusions hold.
void WriteSummaryMarkdown(std::ostream& out, const std::vector<MethodSummary>& summaries,
                          const std::vector<RowConfig>& rows, const ExperimentConfig& config);

// timing.csv: the wall time the triggers' passes took on this machine. It varies from run to run
// (and with the thread count), so it stays out of the tables above, which repeat byte for byte.
constexpr const char* kTimingColumns = "row,method,attempts,init,compute_s,us_per_attempt,us_per_init";
std::string TimingCsvFields(const MethodSummary& summary, const std::vector<RowConfig>& rows);

struct RunInfo {
  std::string config_path;
  int threads = 1;
  double wall_time_s = 0.0;
  std::vector<std::string> sweep_axes;  // "KEY=VALUES" of a sweep, empty for run
};
// manifest.json: resolved config, seed, realizations, threads, git revision, compiler, wall time.
std::string ManifestJson(const ExperimentConfig& config, const RunInfo& info);

}  // namespace anchorbench::experiments
