#include "anchorbench/engine/run_plan.hpp"

#include <map>

namespace anchorbench::engine {
namespace {

int UnitsOf(const ChunkSpan& span) { return span.end_unit - span.first_unit; }

}  // namespace

std::vector<ExperimentAttempts> Join(const Plan& plan, std::map<int, ChunkResult>& chunks) {
  std::vector<ExperimentAttempts> joined(plan.experiments().size());
  for (auto& [chunk, result] : chunks) {  // in chunk order: experiment by experiment, unit by unit
    ExperimentAttempts& into = joined[static_cast<std::size_t>(plan.chunks()[static_cast<std::size_t>(chunk)].experiment)];
    for (schema::Attempt& attempt : result.attempts) into.attempts.push_back(std::move(attempt));
    into.lines += result.lines;
  }
  return joined;
}

std::map<int, ChunkResult> RunPlan(const Plan& plan, Executor& executor, const RunPlanOptions& options) {
  std::map<int, ChunkResult> chunks;
  if (options.store) chunks = options.store->TakeFinished();
  std::erase_if(chunks, [&](const auto& entry) { return !options.shard.Holds(entry.first); });
  long long units_done = 0, units = 0;
  std::vector<int> missing;
  for (int chunk = 0; chunk < static_cast<int>(plan.chunks().size()); ++chunk) {
    if (!options.shard.Holds(chunk)) continue;
    units += UnitsOf(plan.chunks()[static_cast<std::size_t>(chunk)]);
    if (chunks.count(chunk)) {
      units_done += UnitsOf(plan.chunks()[static_cast<std::size_t>(chunk)]);
    } else {
      missing.push_back(chunk);
    }
  }
  if (options.progress) options.progress(units_done, units);
  executor.Compute(plan, missing, options.threads, [&](int chunk, ChunkResult&& result, const std::string& text) {
    if (options.store) options.store->Save(chunk, text);
    chunks.emplace(chunk, std::move(result));
    units_done += UnitsOf(plan.chunks()[static_cast<std::size_t>(chunk)]);
    if (options.progress) options.progress(units_done, units);
  });
  return chunks;
}

std::vector<ExperimentAttempts> RunWholePlan(const Plan& plan, Executor& executor, int threads,
                                             const std::function<void(long long, long long)>& progress) {
  std::map<int, ChunkResult> chunks = RunPlan(plan, executor, {threads, nullptr, progress, {}});
  return Join(plan, chunks);
}

}  // namespace anchorbench::engine
