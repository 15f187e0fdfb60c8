#pragma once
// A plan (or a shard of it) from start to end: the chunks a store already holds, the rest computed
// by an executor (and saved as they come); then every experiment's attempts joined in unit order.

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "anchorbench/engine/attempt.hpp"
#include "anchorbench/engine/chunk_store.hpp"
#include "anchorbench/engine/executor.hpp"
#include "anchorbench/engine/plan.hpp"
#include "anchorbench/engine/shard.hpp"

namespace anchorbench::engine {

// One experiment's attempts in unit order, each with its attempts.csv line: its chunks joined.
using ExperimentAttempts = ChunkResult;

struct RunPlanOptions {
  int threads = 1;                  // per process
  ChunkStore* store = nullptr;      // keeps finished chunks (none: in memory only)
  // (units done, units in the plan), from one thread at a time; resumed units count as done.
  std::function<void(long long, long long)> progress;
  Shard shard{};  // only this shard's chunks (default: all)
};

// The shard's chunks, by index.
std::map<int, ChunkResult> RunPlan(const Plan& plan, Executor& executor, const RunPlanOptions& options);

// Every chunk of the plan, joined per experiment (moved out of `chunks`).
std::vector<ExperimentAttempts> Join(const Plan& plan, std::map<int, ChunkResult>& chunks);

// The whole plan in memory, joined: RunPlan without a store or a shard, then Join.
std::vector<ExperimentAttempts> RunWholePlan(const Plan& plan, Executor& executor, int threads,
                                             const std::function<void(long long, long long)>& progress = nullptr);

}  // namespace anchorbench::engine
