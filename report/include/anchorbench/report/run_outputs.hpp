#pragma once

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "anchorbench/report/summary.hpp"
#include "anchorbench/schema/attempt.hpp"
#include "anchorbench/schema/experiment.hpp"

namespace anchorbench::report {

// attempts.csv: one row per attempt, columns
// row,realization,anchor_id,method,initialized,t_init,n_used,pdop_est,pdop_true,crlb_m,err_m,
// err_x,err_y,err_z,bias_err,alpha,status,bias_aware_dop,..., then why an attempt that did not
// initialize waits (blocked_by, its value and limit) and the oracle's time (t_first, t_oracle,
// latency = (t_init - t_first) / (t_oracle - t_first)), then the ideal region's time and its ratio
// to the oracle's (t_ideal, ideal_latency: the anchor's, the same for every trigger); empty where
// not applicable, never NaN.
constexpr const char* kAttemptsColumns =
    "row,realization,anchor_id,method,initialized,t_init,n_used,pdop_est,pdop_true,crlb_m,err_m,err_x,err_y,err_z,"
    "bias_err,alpha,status,bias_aware_dop,nees_pos,nees,bias_aware_hdop,bias_aware_vdop,blocked_by,blocked_value,"
    "blocked_limit,t_first,t_oracle,latency,t_ideal,ideal_latency";
void WriteAttempts(std::ostream& out, const std::vector<schema::Attempt>& attempts,
                   const std::vector<schema::RowConfig>& rows);
// One attempt's line of attempts.csv, without its line break.
std::string AttemptLine(const schema::Attempt& attempt, const std::vector<schema::RowConfig>& rows);
// The same file from lines written before (engine::ChunkResult's, each ending in a newline): the
// header, then the lines.
void WriteAttemptLines(std::ostream& out, std::string_view lines);

// summary.csv: row,method,avg_m,med_m,init,gt1m,ratio_pct,avg_lo,avg_hi,ratio_lo,ratio_hi, the
// position credibility, med_lo,med_hi, then the initialization times and, where rows carry the paper's values, those.
constexpr const char* kSummaryColumns =
    "row,method,avg_m,med_m,init,gt1m,ratio_pct,avg_lo,avg_hi,ratio_lo,ratio_hi,anees_pos,anees_lo,anees_hi,"
    "nees_gt95_pct,med_lo,med_hi,oracle_n,latency_n,latency_med,latency_p90";
std::string SummaryCsvFields(const MethodSummary& summary, const std::vector<schema::RowConfig>& rows);
void WriteSummaryCsv(std::ostream& out, const std::vector<MethodSummary>& summaries,
                     const std::vector<schema::RowConfig>& rows);

// A markdown table's latency cell: the median (90th percentile) of (t_init - t_first) / (t_oracle -
// t_first) over the initialized attempts the oracle reaches (eval/oracle_latency.hpp), "1.65x
// (2.31x)"; "-" where there is none.
std::string LatencyCell(const MethodSummary& summary);
// The sentence under a markdown table that says what the latency cell is.
constexpr const char* kLatencyNote =
    "Latency: t_init over t_oracle, the earliest time after which the anchor's solver on the accepted samples stays "
    "within D (estimator.certificate.accuracy_m) of the truth, both from the anchor's first sample; the median (90th "
    "percentile) over the initialized attempts the oracle reaches.";

// summary.md: our table, and where rows carry the paper's values, the two side by side cell by
// cell with the relative difference, and whether the paper's conclusions hold.
void WriteSummaryMarkdown(std::ostream& out, const std::vector<MethodSummary>& summaries,
                          const std::vector<schema::RowConfig>& rows, const schema::ExperimentConfig& config);

// timing.csv: the wall time the triggers' passes took on this machine. It varies from run to run
// (and with the thread count), so it stays out of the tables above, which repeat byte for byte.
constexpr const char* kTimingColumns = "row,method,attempts,init,compute_s,us_per_attempt,us_per_init";
std::string TimingCsvFields(const MethodSummary& summary, const std::vector<schema::RowConfig>& rows);
void WriteTimingCsv(std::ostream& out, const std::vector<MethodSummary>& summaries,
                    const std::vector<schema::RowConfig>& rows);

// What a manifest records besides the config.
struct RunInfo {
  std::string config_path;
  std::string revision;  // of the build that ran (the app reads it)
  int threads = 1;
  double wall_time_s = 0.0;
  std::vector<std::string> command_line;  // what the command line changed: --seed 3, --set a.b=c, ...
  std::vector<std::string> sweep_axes;    // "KEY=VALUES" of a sweep, empty for run
  nlohmann::ordered_json resolved_config;  // the config as it ran (config::ToJson)
};
// manifest.json: config file, seed, realizations, threads, revision, compiler, wall time, the
// command line's changes, the sweep axes and the resolved config.
std::string ManifestJson(const schema::ExperimentConfig& config, const RunInfo& info);

}  // namespace anchorbench::report
