#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "anchorbench/eval/credibility.hpp"
#include "anchorbench/schema/attempt.hpp"
#include "anchorbench/schema/random_streams.hpp"
#include "anchorbench/schema/experiment.hpp"

namespace anchorbench::report {

// Table I's columns for one row and trigger, over its initialized attempts.
struct MethodSummary {
  int row = 0;
  std::string method;  // the trigger's name
  int attempts = 0;
  int init = 0;                      // initialized attempts
  std::optional<double> avg_m;       // mean error (absent when init = 0: never NaN)
  std::optional<double> med_m;       // median error
  int gt1m = 0;                      // initialized with error > 1 m
  std::optional<double> ratio_pct;   // 100 gt1m / init
  std::optional<double> t_init_mean_s, t_init_med_s;  // when the initialized attempts initialized
  // Avg and Med: the 95% percentile intervals of a bootstrap over realizations (whole realizations
  // are resampled: the anchors of one realization share a trajectory, so they are not
  // independent), drawn from the stream (seed, row, schema::kBootstrapStream, a hash of the method's name);
  // both from the same resamples.
  // Ratio: the 95% Wilson score interval of gt1m out of init, which stays meaningful at 0 or init
  // failures (a bootstrap there collapses to [0, 0]). It treats the initializations as independent.
  std::optional<double> avg_lo, avg_hi, ratio_lo, ratio_hi, med_lo, med_hi;
  // The credibility of the initialized attempts' position covariances (3-dof NEES; docs/method.md).
  eval::Credibility position_credibility;
  // Against the oracle (eval/oracle_latency.hpp): the attempts whose anchor the oracle certifies at
  // all, the initialized ones of those with a latency, and its median and 90th percentile.
  int oracle_n = 0;
  int latency_n = 0;
  std::optional<double> latency_med, latency_p90;
  double compute_s = 0.0;  // summed Attempt::compute_s (timing files only)
};


// The 95% Wilson score interval of a proportion successes / trials, in [0, 1]; absent for no trials.
struct Interval {
  double lo = 0.0, hi = 0.0;
};
std::optional<Interval> WilsonInterval(int successes, int trials);

// The q-quantile (0..1) with linear interpolation; absent for no values.
std::optional<double> Percentile(std::vector<double> values, double q);
// The arithmetic mean; absent for no values.
std::optional<double> Mean(const std::vector<double>& values);
// A bootstrap substream named by a method (FNV-1a of the name, cut to the substream's 24 bits):
// adding a method leaves the others' intervals as they were.
std::uint32_t MethodSubstream(const std::string& method);

// Summaries ordered by row, then by the row's trigger list (estimator.triggers; the default puts
// fixed_window first, the paper's order). `rows` are the ones the attempts were run on.
std::vector<MethodSummary> Summarize(const std::vector<schema::Attempt>& attempts, const std::vector<schema::RowConfig>& rows,
                                     int realizations, int bootstrap_resamples, std::uint64_t seed);

}  // namespace anchorbench::report
