#include "anchorbench/engine/job.hpp"

#include <map>

#include "anchorbench/engine/chunk.hpp"

namespace anchorbench::engine {

std::optional<std::vector<ExperimentAttempts>> ComputeJob(const Job& job, Executor& executor,
                                                          const JobOptions& options, io::ResultFolder& out) {
  const Shard shard = options.shard.value_or(Shard{});
  ChunkStore store(out.target(), job.plan, options.store_mode, ChunkBytes(job.plan, shard), options.inputs);
  if (store.unreadable() > 0 && options.note) {
    options.note(store.folder().string() + ": " + std::to_string(store.unreadable()) +
                 " stored chunk(s) do not read back (first: " + store.first_unreadable() + "); computing them again");
  }
  std::map<int, ChunkResult> chunks = RunPlan(job.plan, executor, {options.threads, &store, options.progress, shard});
  if (!options.shard) return Join(job.plan, chunks);
  const ShardInfo info{shard, static_cast<int>(chunks.size()), job.command, job.name, job.plan.identity(), job.revision};
  WriteShardFolder([&](const std::string& name, const std::string& text) { out.Write(name, text); }, info, job.inputs,
                   job.plan, chunks);
  out.Commit();
  store.Remove();
  return std::nullopt;
}

void RemoveStore(const io::ResultFolder& out) {
  std::error_code error;
  std::filesystem::remove_all(ChunkStorePath(out.target()), error);
}

}  // namespace anchorbench::engine
