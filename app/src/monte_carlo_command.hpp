#pragma once
// What run, sweep and pdop-study share: the thread count, the output folder, progress, and the
// manifest's record of the run.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/report/run_outputs.hpp"
#include "anchorbench/runner/experiment.hpp"
#include "anchorbench/work/chunk_store.hpp"
#include "commands.hpp"
#include "progress.hpp"

namespace anchorbench::app {

struct MonteCarloSetup {
  int threads = 1;
  std::filesystem::path out;
};
// Resolves the thread count and where the results go; call it only once the input is valid.
MonteCarloSetup SetUpMonteCarlo(const MonteCarloArgs& args, const std::string& config_name);

// The result folder, before any work: refused if it holds earlier results without --overwrite,
// checked for being writable, with `expected_bytes` reserved on its disk.
std::unique_ptr<io::ResultFolder> OpenResultFolder(const MonteCarloArgs& args, const MonteCarloSetup& setup,
                                                  std::uintmax_t expected_bytes);

// Where run and sweep keep finished chunks: --resume takes them, --overwrite discards them, and
// otherwise an interrupted run's store is refused.
work::ChunkStore::Mode StoreMode(const MonteCarloArgs& args);

// A run's summary tables from its attempts (run and merge write the same): summary.csv,
// summary.md and timing.csv into `out`; returns summary.md's text.
std::string WriteRunTables(io::ResultFolder& out, const std::vector<runner::Attempt>& attempts,
                           const std::vector<runner::RowConfig>& rows, const runner::ExperimentConfig& config);

// The manifest's record: the command line's changes (--realizations and any `more`), threads,
// wall time, revision and the resolved config.
report::RunInfo RunInfoOf(const MonteCarloArgs& args, const MonteCarloSetup& setup, const AppContext& app,
                          const runner::ExperimentConfig& config, double wall_time_s,
                          std::vector<std::string> more_command_line = {});

}  // namespace anchorbench::app
