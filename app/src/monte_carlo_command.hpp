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
#include "anchorbench/engine/chunk_store.hpp"
#include "anchorbench/engine/record_journal.hpp"
#include "anchorbench/engine/job.hpp"
#include "anchorbench/engine/shard.hpp"
#include "anchorbench/studies/record_study.hpp"
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

// How the store beside the result folder is taken: --resume, --overwrite, or fresh.
engine::ChunkStore::Mode StoreMode(const MonteCarloArgs& args);
// A note on stderr (even with --quiet) when the journal held units that did not read back.
void NoteUnreadable(const engine::RecordJournal& journal);

// Which share of the plan --shard asks for (none: all of it).
std::optional<engine::Shard> ShardOf(const MonteCarloArgs& args);

// The job computed (engine/job.hpp) with the command line's store mode, shard and threads, with
// progress on stderr (and a damaged store's note, even with --quiet).
struct PlanOutcome {
  std::optional<std::vector<engine::ExperimentAttempts>> experiments;  // none for a shard: its folder is written
  double wall_time_s = 0.0;
};
PlanOutcome ComputePlan(const MonteCarloArgs& args, const MonteCarloSetup& setup, const engine::Job& job,
                        const AppContext& app, io::ResultFolder& out);

// The manifest's record: the command line's changes (--realizations and any `more`), threads,
// wall time, revision and the resolved config.
report::RunInfo RunInfoOf(const MonteCarloArgs& args, const MonteCarloSetup& setup, const AppContext& app,
                          const schema::ExperimentConfig& config, double wall_time_s,
                          std::vector<std::string> more_command_line = {});
// `command` (if not empty), then "--set KEY=VALUE" for each override: the manifest's words for them.
std::vector<std::string> CommandLine(const std::string& command, const std::vector<std::string>& overrides);

}  // namespace anchorbench::app
