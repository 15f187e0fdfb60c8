#pragma once
// A plan from start to end: the chunks a store already holds, the rest computed by an executor
// (and saved as they come), then every experiment's attempts joined in unit order.

#include <functional>
#include <string>
#include <vector>

#include "anchorbench/runner/attempt.hpp"
#include "anchorbench/work/chunk_store.hpp"
#include "anchorbench/work/executor.hpp"
#include "anchorbench/work/plan.hpp"

namespace anchorbench::work {

// One experiment's attempts in unit order, each with its attempts.csv line.
struct ExperimentAttempts {
  std::vector<runner::Attempt> attempts;
  std::vector<std::string> lines;
};

struct RunPlanOptions {
  int threads = 1;                  // per process
  ChunkStore* store = nullptr;      // keeps finished chunks (none: in memory only)
  // (units done, units in the plan), from one thread at a time; resumed units count as done.
  std::function<void(long long, long long)> progress;
};

std::vector<ExperimentAttempts> RunPlan(const Plan& plan, Executor& executor, const RunPlanOptions& options);

}  // namespace anchorbench::work
