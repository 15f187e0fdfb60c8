#pragma once
// What run, sweep and pdop-study share: the thread count, the output folder, progress, and the
// manifest's record of the run.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/report/run_outputs.hpp"
#include "anchorbench/schema/experiment.hpp"
#include "anchorbench/schema/sweep.hpp"
#include "anchorbench/engine/run_plan.hpp"
#include "anchorbench/engine/shard_folder.hpp"
#include "commands.hpp"
#include "progress.hpp"

namespace anchorbench::app {

struct MonteCarloSetup {
  int threads = 1;
  std::filesystem::path out;
};
// Resolves the thread count and where the results go; call it only once the input is valid.
MonteCarloSetup SetUpMonteCarlo(const MonteCarloArgs& args, const std::string& config_name);

// Every file the command reads: the config and its bases (never overwritten or deleted).
std::vector<std::filesystem::path> InputsOf(const MonteCarloArgs& args);

// The result folder, before any work: refused if it holds earlier results without --overwrite or
// one of the command's inputs, checked for being writable, with `expected_bytes` reserved on its disk.
std::unique_ptr<io::ResultFolder> OpenResultFolder(const MonteCarloArgs& args, const MonteCarloSetup& setup,
                                                  std::uintmax_t expected_bytes);

// The bytes run and sweep claim for their results: a run's attempts.csv (lines of 250-310 bytes)
// and tables; a shard's folder of chunk files.
std::uintmax_t RunResultBytes(const engine::Plan& plan, const MonteCarloArgs& args);

// What run and sweep share once their plan is made: which command on which experiment, and what
// a shard folder records to rebuild the plan.
struct PlanJob {
  const engine::Plan& plan;
  std::string command;  // "run" or "sweep"
  std::string name;     // the experiment's
  engine::ShardInputs inputs;
};
struct PlanOutcome {
  std::optional<std::vector<engine::ExperimentAttempts>> experiments;  // none for a shard: its folder is written
  double wall_time_s = 0.0;
};
// Computes the job's chunks (all, or --shard's) into the chunk store beside `out` (--resume takes
// its chunks, --overwrite discards them, an interrupted store is otherwise refused; the space of
// the chunks still to come is claimed first), with progress. A shard's chunks become its shard folder, committed here; a whole plan's come back
// joined for the command to commit, after which RemoveStore(out).
PlanOutcome ComputePlan(const MonteCarloArgs& args, const MonteCarloSetup& setup, const PlanJob& job,
                        const AppContext& app, io::ResultFolder& out);
void RemoveStore(const io::ResultFolder& out);

// A run's results from its attempts (run and merge write the same): attempts.csv, summary.csv,
// summary.md, timing.csv and manifest.json into `out`, committed; returns summary.md's text.
std::string CommitRun(io::ResultFolder& out, const schema::ExperimentConfig& config,
                      const engine::ExperimentAttempts& run, const report::RunInfo& info);

// A sweep's results (sweep and merge): sweep.csv, timing.csv, sweep.md and manifest.json, committed;
// returns sweep.md's text. `plan` holds one experiment per grid point of `axes`.
std::string CommitSweep(io::ResultFolder& out, const std::string& name, const std::vector<schema::SweepAxis>& axes,
                        const engine::Plan& plan, const std::vector<engine::ExperimentAttempts>& points,
                        report::RunInfo info);

// The manifest's record: the command line's changes (--realizations and any `more`), threads,
// wall time, revision and the resolved config.
report::RunInfo RunInfoOf(const MonteCarloArgs& args, const MonteCarloSetup& setup, const AppContext& app,
                          const schema::ExperimentConfig& config, double wall_time_s,
                          std::vector<std::string> more_command_line = {});

}  // namespace anchorbench::app
