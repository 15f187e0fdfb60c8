#include "anchorbench/report/summary.hpp"

#include <algorithm>
#include <cmath>

#include "anchorbench/sim/random_stream.hpp"

namespace anchorbench::report {

using schema::Attempt;
namespace {

// One realization of one (row, method): its sums rebuild Avg of any resample, its errors the median.
struct RealizationSums {
  double error_sum_m = 0.0;
  int init = 0;
  int gt1m = 0;
  std::vector<double> errors_m;
};

// Percentile(values, 0.5) without a copy: reorders `values`.
double MedianInPlace(std::vector<double>& values) {
  const std::size_t i = (values.size() - 1) / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(i), values.end());
  const double lower = values[i];
  if (values.size() % 2 == 1) return lower;
  const double upper = *std::min_element(values.begin() + static_cast<std::ptrdiff_t>(i) + 1, values.end());
  return lower + 0.5 * (upper - lower);
}

MethodSummary SummarizeOne(const std::vector<const Attempt*>& attempts, const std::vector<RealizationSums>& sums,
                           int bootstrap_resamples, sim::RandomStream rng) {
  MethodSummary s;
  std::vector<double> errors, times, nees, latencies;
  for (const Attempt* a : attempts) {
    ++s.attempts;
    s.compute_s += a->compute_s;
    if (a->evaluation && a->evaluation->t_oracle_s) ++s.oracle_n;
    if (a->initialized && a->evaluation->latency_ratio) latencies.push_back(*a->evaluation->latency_ratio);
    if (!a->initialized) continue;
    ++s.init;
    errors.push_back(*a->evaluation->error_m);
    times.push_back(*a->t_init_s);
    s.gt1m += *a->evaluation->error_m > 1.0;
    if (a->evaluation->nees_position) nees.push_back(*a->evaluation->nees_position);
  }
  s.latency_n = static_cast<int>(latencies.size());
  s.latency_med = Percentile(latencies, 0.5);
  s.latency_p90 = Percentile(latencies, 0.9);
  if (s.init == 0) return s;
  s.position_credibility = eval::CredibilityOf(nees, 3);
  double total = 0.0, total_time = 0.0;
  for (double e : errors) total += e;
  for (double t : times) total_time += t;
  s.avg_m = total / s.init;
  s.t_init_mean_s = total_time / s.init;
  s.t_init_med_s = Percentile(times, 0.5);
  s.med_m = Percentile(errors, 0.5);
  s.ratio_pct = 100.0 * s.gt1m / s.init;

  std::vector<double> avg_samples, med_samples, pooled_errors_m;
  pooled_errors_m.reserve(2 * errors.size());
  const int realizations = static_cast<int>(sums.size());
  for (int b = 0; b < bootstrap_resamples; ++b) {
    RealizationSums resample;
    pooled_errors_m.clear();
    for (int k = 0; k < realizations; ++k) {
      const RealizationSums& pick = sums[static_cast<std::size_t>(rng.Uniform() * realizations)];
      resample.error_sum_m += pick.error_sum_m;
      resample.init += pick.init;
      resample.gt1m += pick.gt1m;
      pooled_errors_m.insert(pooled_errors_m.end(), pick.errors_m.begin(), pick.errors_m.end());
    }
    if (resample.init == 0) continue;
    avg_samples.push_back(resample.error_sum_m / resample.init);
    med_samples.push_back(MedianInPlace(pooled_errors_m));
  }
  s.avg_lo = Percentile(avg_samples, 0.025);
  s.avg_hi = Percentile(avg_samples, 0.975);
  s.med_lo = Percentile(med_samples, 0.025);
  s.med_hi = Percentile(med_samples, 0.975);
  const Interval ratio = *WilsonInterval(s.gt1m, s.init);
  s.ratio_lo = 100.0 * ratio.lo;
  s.ratio_hi = 100.0 * ratio.hi;
  return s;
}

}  // namespace

std::optional<Interval> WilsonInterval(int successes, int trials) {
  if (trials <= 0) return std::nullopt;
  constexpr double kZ = 1.959963984540054;  // the standard normal's 97.5% quantile
  const double n = trials;
  const double p = successes / n;
  const double z2_n = kZ * kZ / n;
  const double centre = (p + z2_n / 2.0) / (1.0 + z2_n);
  const double half = kZ * std::sqrt(p * (1.0 - p) / n + z2_n / (4.0 * n)) / (1.0 + z2_n);
  return Interval{std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

std::optional<double> Mean(const std::vector<double>& values) {
  if (values.empty()) return std::nullopt;
  double sum = 0.0;
  for (double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

std::optional<double> Percentile(std::vector<double> values, double q) {
  if (values.empty()) return std::nullopt;
  std::sort(values.begin(), values.end());
  const double position = q * static_cast<double>(values.size() - 1);
  const auto i = static_cast<std::size_t>(position);
  const double fraction = position - static_cast<double>(i);
  return i + 1 < values.size() ? values[i] + fraction * (values[i + 1] - values[i]) : values[i];
}

std::uint32_t MethodSubstream(const std::string& method) {
  std::uint32_t hash = 2166136261u;
  for (const char c : method) hash = (hash ^ static_cast<unsigned char>(c)) * 16777619u;
  return hash & sim::RandomStream::kMaxSubstream;
}

std::vector<MethodSummary> Summarize(const std::vector<Attempt>& attempts, const std::vector<schema::RowConfig>& rows,
                                     int realizations, int bootstrap_resamples, std::uint64_t seed) {
  std::vector<MethodSummary> summaries;
  for (int row = 0; row < static_cast<int>(rows.size()); ++row) {
    for (const std::string& method : rows[static_cast<std::size_t>(row)].estimator.triggers) {
      std::vector<const Attempt*> selected;
      std::vector<RealizationSums> sums(static_cast<std::size_t>(realizations));
      for (const Attempt& a : attempts) {
        if (a.row != row || a.method != method) continue;
        selected.push_back(&a);
        if (!a.initialized) continue;
        RealizationSums& r = sums[static_cast<std::size_t>(a.realization)];
        r.error_sum_m += *a.evaluation->error_m;
        ++r.init;
        r.gt1m += *a.evaluation->error_m > 1.0;
        r.errors_m.push_back(*a.evaluation->error_m);
      }
      // One bootstrap stream per (row, method), named by them rather than numbered in table order:
      // adding a trigger to a config leaves the other methods' intervals as they were.
      MethodSummary s = SummarizeOne(selected, sums, bootstrap_resamples,
                                     sim::RandomStream(seed, static_cast<std::uint64_t>(row), schema::kBootstrapStream,
                                                       MethodSubstream(method)));
      s.row = row;
      s.method = method;
      summaries.push_back(s);
    }
  }
  return summaries;
}

}  // namespace anchorbench::report
