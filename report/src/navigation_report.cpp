#include "anchorbench/report/navigation_report.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "anchorbench/io/format.hpp"
#include "anchorbench/report/summary.hpp"
#include "anchorbench/schema/random_streams.hpp"
#include "anchorbench/sim/random_stream.hpp"

namespace anchorbench::report {
namespace {

using io::FormatFixed;
using io::FormatWithInterval;
using io::FormatNumber;
using io::FormatOptional;

// The 95% percentile interval of the mean over `resamples` resamples of the runs (one a realization).
std::pair<double, double> BootstrapMean(const std::vector<double>& values, int resamples, sim::RandomStream rng) {
  std::vector<double> means;
  means.reserve(static_cast<std::size_t>(resamples));
  for (int b = 0; b < resamples; ++b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i) {
      sum += values[std::min(values.size() - 1, static_cast<std::size_t>(rng.Uniform() * static_cast<double>(values.size())))];
    }
    means.push_back(sum / static_cast<double>(values.size()));
  }
  return {*Percentile(means, 0.025), *Percentile(means, 0.975)};
}

}  // namespace

std::vector<NavigationSummary> SummarizeNavigation(const std::vector<nav::NavigationRecord>& records, int rows,
                                                   int resamples, std::uint64_t seed, const std::string& drift_method) {
  std::map<std::pair<int, int>, double> drift_rmse;  // by (row, realization)
  for (const nav::NavigationRecord& r : records) {
    if (r.method == drift_method) drift_rmse[{r.row, r.realization}] = r.outcome.rmse_m;
  }
  std::vector<NavigationSummary> summaries;
  for (int row = 0; row < rows; ++row) {
    std::vector<std::string> methods;  // in the records' order
    for (const nav::NavigationRecord& r : records) {
      if (r.row == row && std::find(methods.begin(), methods.end(), r.method) == methods.end()) methods.push_back(r.method);
    }
    for (const std::string& method : methods) {
      std::vector<double> rmse, final_error, fix, t_first, t_kth;
      int worse = 0;
      for (const nav::NavigationRecord& r : records) {
        if (r.row != row || r.method != method) continue;
        const auto drift = drift_rmse.find({r.row, r.realization});
        worse += drift != drift_rmse.end() && r.outcome.rmse_m > drift->second;
        rmse.push_back(r.outcome.rmse_m);
        final_error.push_back(r.outcome.final_error_m);
        fix.push_back(r.outcome.fix_share);
        if (r.outcome.t_first_anchor_s) t_first.push_back(*r.outcome.t_first_anchor_s);
        if (r.outcome.t_kth_anchor_s) t_kth.push_back(*r.outcome.t_kth_anchor_s);
      }
      NavigationSummary s;
      s.row = row;
      s.method = method;
      s.runs = static_cast<int>(rmse.size());
      s.rmse_mean_m = Mean(rmse).value_or(0.0);
      if (resamples > 0) {
        const auto [lo, hi] = BootstrapMean(rmse, resamples,
                                            sim::RandomStream(seed, static_cast<std::uint64_t>(row), schema::kBootstrapStream,
                                                              MethodSubstream("navigation:" + method)));
        s.rmse_lo_m = lo;
        s.rmse_hi_m = hi;
      }
      s.final_error_median_m = Percentile(final_error, 0.5).value_or(0.0);
      s.fix_share_mean = Mean(fix).value_or(0.0);
      s.with_first_anchor = static_cast<int>(t_first.size());
      s.t_first_anchor_median_s = Percentile(t_first, 0.5);
      s.t_kth_anchor_median_s = Percentile(t_kth, 0.5);
      if (method != drift_method && !drift_rmse.empty()) s.worse_than_drift = worse;
      summaries.push_back(s);
    }
  }
  return summaries;
}

void WriteNavigationCsv(std::ostream& out, const std::vector<nav::NavigationRecord>& records,
                        const std::vector<schema::RowConfig>& rows) {
  out << "row,realization,method,rmse_m,final_error_m,t_first_anchor_s,t_kth_anchor_s,fix_share,ranges_used,"
         "ranges_gated\n";
  for (const nav::NavigationRecord& r : records) {
    const nav::NavigationOutcome& o = r.outcome;
    out << rows[static_cast<std::size_t>(r.row)].name << ',' << r.realization << ',' << r.method << ','
        << FormatNumber(o.rmse_m) << ',' << FormatNumber(o.final_error_m) << ',' << FormatOptional(o.t_first_anchor_s)
        << ',' << FormatOptional(o.t_kth_anchor_s) << ',' << FormatNumber(o.fix_share) << ',' << o.ranges_used << ','
        << o.ranges_gated << '\n';
  }
}

void WriteNavigationErrorCsv(std::ostream& out, const std::vector<nav::NavigationRecord>& records,
                             const std::vector<schema::RowConfig>& rows, double error_bin_s) {
  out << "row,method,t_s,runs,error_mean_m,error_p90_m\n";
  std::vector<std::pair<int, std::string>> series;  // (row, method) in the records' order
  std::map<std::pair<int, std::string>, std::vector<std::vector<double>>> by_bin;  // the realizations' bin errors
  for (const nav::NavigationRecord& r : records) {
    const std::pair<int, std::string> key{r.row, r.method};
    auto [at, fresh] = by_bin.try_emplace(key);
    if (fresh) series.push_back(key);
    std::vector<std::vector<double>>& bins = at->second;
    if (bins.size() < r.outcome.error_by_bin_m.size()) bins.resize(r.outcome.error_by_bin_m.size());
    for (std::size_t b = 0; b < r.outcome.error_by_bin_m.size(); ++b) {
      if (std::isfinite(r.outcome.error_by_bin_m[b])) bins[b].push_back(r.outcome.error_by_bin_m[b]);
    }
  }
  for (const auto& key : series) {
    const std::vector<std::vector<double>>& bins = by_bin.at(key);
    for (std::size_t b = 0; b < bins.size(); ++b) {
      if (bins[b].empty()) continue;
      out << rows[static_cast<std::size_t>(key.first)].name << ',' << key.second << ','
          << FormatNumber((static_cast<double>(b) + 0.5) * error_bin_s) << ',' << bins[b].size() << ','
          << FormatNumber(*Mean(bins[b])) << ',' << FormatNumber(*Percentile(bins[b], 0.9)) << '\n';
    }
  }
}

void WriteNavigationSummaryCsv(std::ostream& out, const std::vector<NavigationSummary>& summaries,
                               const std::vector<schema::RowConfig>& rows) {
  out << "row,method,runs,rmse_mean_m,rmse_lo_m,rmse_hi_m,final_error_median_m,fix_share_mean,with_first_anchor,"
         "t_first_anchor_median_s,t_kth_anchor_median_s,worse_than_drift\n";
  for (const NavigationSummary& s : summaries) {
    out << rows[static_cast<std::size_t>(s.row)].name << ',' << s.method << ',' << s.runs << ','
        << FormatNumber(s.rmse_mean_m) << ',' << FormatOptional(s.rmse_lo_m) << ',' << FormatOptional(s.rmse_hi_m) << ','
        << FormatNumber(s.final_error_median_m) << ',' << FormatNumber(s.fix_share_mean) << ',' << s.with_first_anchor
        << ',' << FormatOptional(s.t_first_anchor_median_s) << ',' << FormatOptional(s.t_kth_anchor_median_s) << ','
        << (s.worse_than_drift ? std::to_string(*s.worse_than_drift) : "") << '\n';
  }
}

void WriteNavigationMarkdown(std::ostream& out, const std::vector<NavigationSummary>& summaries,
                             const std::vector<schema::RowConfig>& rows, const schema::ExperimentConfig& config) {
  out << "# " << config.name << ": navigation\n\n" << config.realizations << " realizations per row, seed " << config.seed
      << ". Position RMSE over the run (mean, 95% interval over realizations), end error (median), share of the run "
         "with a fix, when the first and k-th anchors came (medians), and the share of runs navigating worse (higher "
         "RMSE) than odometry alone in the same realization.\n\n"
      << "| Row | Method | RMSE (m) | End error (m) | Fix (%) | First anchor (s) | k-th anchor (s) | Worse than none (%) |\n"
      << "|---|---|---|---|---|---|---|---|\n";
  for (const NavigationSummary& s : summaries) {
    out << "| " << rows[static_cast<std::size_t>(s.row)].name << " | " << s.method << " | "
        << FormatWithInterval(s.rmse_mean_m, s.rmse_lo_m, s.rmse_hi_m, 3) << " | "
        << FormatFixed(s.final_error_median_m, 3) << " | " << FormatFixed(100.0 * s.fix_share_mean, 1) << " | "
        << FormatFixed(s.t_first_anchor_median_s, 1) << " | " << FormatFixed(s.t_kth_anchor_median_s, 1) << " | "
        << (s.worse_than_drift ? FormatFixed(100.0 * *s.worse_than_drift / s.runs, 0) : "-") << " |\n";
  }
}

}  // namespace anchorbench::report
