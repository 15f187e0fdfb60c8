#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "anchorbench/estimator/solve_result.hpp"
#include "anchorbench/estimator/components.hpp"
#include "anchorbench/experiments/config.hpp"

namespace anchorbench::experiments {

// One anchor in one realization with one strategy (a row of attempts.csv).
struct Attempt {
  int row = 0;
  int realization = 0;
  int anchor_id = 0;
  std::string method;  // the trigger's name
  bool initialized = false;
  std::optional<double> t_init_s;
  int n_used = 0;
  double pdop_estimate = 0.0;
  std::optional<double> pdop_true;
  std::optional<double> crlb_m;  // sigma_d * bias-aware DOP on the attempt's data at the true anchor
  std::optional<double> bias_aware_dop;
  std::optional<double> error_m;
  Eigen::Vector3d error_xyz_m = Eigen::Vector3d::Zero();  // estimate - truth
  std::optional<double> bias_error_m;
  std::optional<double> alpha;
  std::string status;  // the solver's status, or not_triggered / no_data
  double compute_s = 0.0;  // AttemptOutcome::compute_s: timing files only, never attempts.csv
};

// The OpenMP thread count for a request: 0 means every core.
int ResolveThreads(int requested);

struct MonteCarloOptions {
  int threads = 1;
  // Called from one thread at a time with (tasks done, tasks total); tasks are (row, realization).
  std::function<void(int, int)> progress;
  // Where solver, filter and trigger names are looked up (registries with your own parts);
  // default: the built-ins.
  const estimator::Components* components = nullptr;
};

// Runs every row's realizations (parallel over (row, realization) with OpenMP; realization k of
// every row uses the random streams keyed (seed, k), so rows differ only by their parameters).
// The result is ordered by row, realization, anchor, method: identical for any thread count.
std::vector<Attempt> RunMonteCarlo(const ExperimentConfig& config, const MonteCarloOptions& options);

// The attempts of one realization of one row (what each task computes). `samples` is scratch,
// reused from call to call by the caller.
std::vector<Attempt> RunRealization(const RowConfig& row, int row_index, std::uint64_t seed, int realization,
                                    const estimator::Components* components,
                                    std::vector<estimator::RangeSample>& samples);

}  // namespace anchorbench::experiments
