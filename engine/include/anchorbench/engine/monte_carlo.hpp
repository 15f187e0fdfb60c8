#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "anchorbench/config/config_yaml.hpp"
#include "anchorbench/estimator/range_sample.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/engine/attempt.hpp"
#include "anchorbench/schema/experiment.hpp"
#include "anchorbench/schema/sweep.hpp"
#include "anchorbench/sim/scenario.hpp"

namespace anchorbench::engine {

// The thread count for a request: `requested` if > 0, else OMP_NUM_THREADS if set, else every
// core. At most kThreadsPerCore x the cores (more only adds overhead, and thousands of threads
// exhaust memory); beyond, or an OMP_NUM_THREADS that is not a count, is an schema::InputError.
constexpr int kThreadsPerCore = 8;
int ResolveThreads(int requested);

// The attempts a run may hold in memory until it writes them (~0.5 KB each): 1e7, ~5 GB.
constexpr double kMaxAttemptsPerRun = 1e7;
// Refuses (schema::InputError) a config whose rows x realizations x anchors x triggers exceed it,
// before any work.
void CheckWork(const schema::ExperimentConfig& config);

struct MonteCarloOptions {
  int threads = 1;
  // Called from one thread at a time with (units done, units total); a unit is a (row, realization).
  std::function<void(long long, long long)> progress;
};

// Builds every row's initializers once, on a stand-in anchor, so that what a realization would
// refuse (an unknown name, a trigger that needs what it lacks) is refused before any trial runs.
// Throws schema::InputError naming the row.
void CheckRows(const std::vector<schema::RowConfig>& rows, const registry::Components& components);

// Both, on the experiment's rows: what every command checks before it plans any work.
void CheckExperiment(const schema::ExperimentConfig& config, const registry::Components& components);

// A sweep's experiments, one per grid point of `axes`: the document (read once) with `overrides`,
// then the point's overrides, then `realizations` if given; each checked (CheckExperiment) before
// any trial runs.
std::vector<schema::ExperimentConfig> SweepPoints(const config::ConfigDocument& document,
                                                  const std::vector<std::string>& overrides,
                                                  const std::vector<schema::SweepAxis>& axes,
                                                  std::optional<int> realizations,
                                                  const registry::Components& components);

// Runs every row's realizations: the experiment checked (CheckExperiment), planned (plan.hpp) and
// computed by this process's threads (LocalExecutor), as `run` does without a store. Realization
// k of every row uses the random streams keyed (seed, k), so rows differ only by their
// parameters. The result is ordered by row, realization, anchor, method: identical for any thread
// count. An error in any unit ends the run with that error.
std::vector<schema::Attempt> RunMonteCarlo(const schema::ExperimentConfig& config, const registry::Components& components,
                                           const MonteCarloOptions& options);

// The attempts of one realization of one row (what each task computes): the simulated samples
// go through one front end per trigger (each trigger's pass is timed on its own). `samples` is
// scratch, reused from call to call by the caller.
std::vector<schema::Attempt> RunRealization(const schema::RowConfig& row, int row_index, std::uint64_t seed, int realization,
                                    const registry::Components& components,
                                    std::vector<estimator::RangeSample>& samples);
// The same on a realization already simulated (sim::GenerateScenario of the row, seed and
// realization), for a caller that needs the scenario too (the navigation study).
std::vector<schema::Attempt> RunRealization(const schema::RowConfig& row, int row_index, std::uint64_t seed, int realization,
                                    const sim::Scenario& scenario, const registry::Components& components,
                                    std::vector<estimator::RangeSample>& samples);

}  // namespace anchorbench::engine
