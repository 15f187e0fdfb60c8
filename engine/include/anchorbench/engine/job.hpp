#pragma once
// A run or a sweep computed into its result folder: the plan's chunks (all, or one shard's) through
// the chunk store beside the folder, so that a killed job resumes. A shard's chunks become its
// shard folder, committed here; a whole plan's come back joined, for CommitRun or CommitSweep.

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "anchorbench/engine/chunk_store.hpp"
#include "anchorbench/engine/executor.hpp"
#include "anchorbench/engine/plan.hpp"
#include "anchorbench/engine/run_plan.hpp"
#include "anchorbench/engine/shard.hpp"
#include "anchorbench/engine/shard_folder.hpp"
#include "anchorbench/io/result_folder.hpp"

namespace anchorbench::engine {

// What a job is, as its shard folder records it.
struct Job {
  const Plan& plan;
  std::string command;   // "run" or "sweep"
  std::string name;      // the experiment's
  std::string revision;  // of this build
  ShardInputs inputs;    // what rebuilds the plan
};

struct JobOptions {
  int threads = 1;
  // kResume takes the store's chunks, kOverwrite discards them; kFresh refuses an interrupted store.
  ChunkStore::Mode store_mode = ChunkStore::Mode::kFresh;
  std::optional<Shard> shard;                 // none: the whole plan
  std::vector<std::filesystem::path> inputs;  // files the job reads (never replaced)
  std::function<void(long long done, long long total)> progress;
  // Told when stored chunks do not read back (a damaged store): they are computed again.
  std::function<void(const std::string&)> note;
};

// The job's chunks computed into `out`'s store (the space of those still to come claimed first).
// For a shard, writes and commits its folder and returns nothing; otherwise returns every
// experiment's attempts, and the caller commits them and then calls RemoveStore.
std::optional<std::vector<ExperimentAttempts>> ComputeJob(const Job& job, Executor& executor,
                                                          const JobOptions& options, io::ResultFolder& out);

// The chunk store of `out`'s job, once its results are committed.
void RemoveStore(const io::ResultFolder& out);

}  // namespace anchorbench::engine
