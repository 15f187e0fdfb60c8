#include "anchorbench/experiments/monte_carlo.hpp"

#include <omp.h>

#include "anchorbench/experiments/anchor_bank.hpp"
#include "anchorbench/sim/scenario.hpp"

namespace anchorbench::experiments {
namespace {

std::string StatusOf(const AttemptOutcome& o) {
  if (o.solve) return std::string(estimator::ToString(o.solve->status));
  return o.n_used == 0 ? "no_data" : "not_triggered";
}

}  // namespace

int ResolveThreads(int requested) { return requested > 0 ? requested : omp_get_num_procs(); }

std::vector<Attempt> RunRealization(const RowConfig& row, int row_index, std::uint64_t seed, int realization,
                                    const estimator::Components* components,
                                    std::vector<estimator::RangeSample>& samples) {
  const sim::Scenario scenario = sim::GenerateScenario(row.scenario, seed, static_cast<std::uint64_t>(realization));
  std::map<int, AnchorTruth> truth;
  for (const sim::SimAnchor& anchor : scenario.anchors) truth[anchor.id] = {anchor.p_world_anchor, anchor.bias_m};
  AnchorBank bank(row.estimator, seed, static_cast<std::uint64_t>(realization), &truth, components);
  for (const sim::SimAnchor& anchor : scenario.anchors) bank.AddAnchor(anchor.id);
  // Ranges come in epoch order, so the reported tag position is the epoch's (no interpolation).
  samples.clear();
  samples.reserve(scenario.ranges.size());
  std::size_t epoch = 0;
  for (const sim::SimRange& range : scenario.ranges) {
    while (scenario.t_s[epoch] < range.t_s) ++epoch;
    samples.push_back({range.t_s, range.tag_id, range.anchor_id, range.range_m,
                       scenario.p_world_tag_reported[static_cast<std::size_t>(range.tag_id)][epoch]});
  }
  const double t_end_s = scenario.t_s.empty() ? 0.0 : scenario.t_s.back();

  std::vector<Attempt> attempts;
  const double sigma_m = row.scenario.ranging.sigma_range_m;
  for (const AttemptOutcome& o : bank.Run(samples, t_end_s)) {
    Attempt a;
    a.row = row_index;
    a.realization = realization;
    a.anchor_id = o.anchor_id;
    a.method = o.method;
    a.initialized = o.initialized;
    a.t_init_s = o.t_init_s;
    a.n_used = o.n_used;
    a.pdop_estimate = o.pdop_estimate;
    a.pdop_true = o.pdop_true;
    if (o.bias_aware_dop && std::isfinite(*o.bias_aware_dop)) {
      a.bias_aware_dop = o.bias_aware_dop;
      a.crlb_m = sigma_m * *o.bias_aware_dop;
    }
    a.status = StatusOf(o);
    a.compute_s = o.compute_s;
    if (o.solve) a.alpha = o.solve->alpha;
    if (o.initialized) {
      const AnchorTruth& t = truth.at(o.anchor_id);
      a.error_m = o.error_m;
      a.error_xyz_m = o.solve->p_world_anchor - t.p_world_anchor;
      a.bias_error_m = o.solve->bias_m - *t.bias_m;
    }
    attempts.push_back(std::move(a));
  }
  return attempts;
}

std::vector<Attempt> RunMonteCarlo(const ExperimentConfig& config, const MonteCarloOptions& options) {
  const std::vector<RowConfig> rows = RowsOf(config);
  const int realizations = config.realizations;
  const int tasks = static_cast<int>(rows.size()) * realizations;
  std::vector<std::vector<Attempt>> per_task(static_cast<std::size_t>(tasks));
  int done = 0;

#pragma omp parallel num_threads(options.threads)
  {
    // One sample buffer per thread: megabytes allocated and freed per realization made glibc
    // return and re-fault the pages every time (+45% run time on Table I).
    std::vector<estimator::RangeSample> samples;
#pragma omp for schedule(dynamic, 1)
    for (int task = 0; task < tasks; ++task) {
      const int row = task / realizations;
      per_task[static_cast<std::size_t>(task)] = RunRealization(rows[static_cast<std::size_t>(row)], row, config.seed,
                                                                task % realizations, options.components, samples);
#pragma omp critical(anchorbench_progress)
      {
        ++done;
        if (options.progress) options.progress(done, tasks);
      }
    }
  }

  std::vector<Attempt> attempts;
  for (auto& task_attempts : per_task) {
    for (Attempt& a : task_attempts) attempts.push_back(std::move(a));
  }
  return attempts;
}

}  // namespace anchorbench::experiments
