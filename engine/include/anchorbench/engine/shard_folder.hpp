#pragma once
// A shard folder (`anchorbench run|sweep|navigate --shard I/N`) and what `anchorbench merge` reads back:
//   shard.csv      shard,of,chunks,command,name,plan,revision: which share of which plan, by which build;
//   config.yaml    the resolved config (--seed, --set, --realizations applied);
//   axes.txt       a sweep's axes, one KEY=VALUES a line (empty for a run);
//   chunk-*.csv    the shard's chunks (chunk.hpp), named by index (navigate: navigation_shard.hpp's
//                  records instead).
// The config and axes rebuild the plan; its identity must be shard.csv's, so an edited folder is
// refused rather than merged.

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "anchorbench/registry/components.hpp"
#include "anchorbench/schema/sweep.hpp"
#include "anchorbench/engine/chunk.hpp"
#include "anchorbench/engine/plan.hpp"
#include "anchorbench/engine/shard.hpp"

namespace anchorbench::engine {

struct ShardInfo {
  Shard shard;
  int chunks = 0;         // chunks this shard holds
  std::string command;    // "run", "sweep" or "navigate"
  std::string name;       // the experiment's name (its file's stem), for the merged tables
  std::string plan;       // the plan's identity
  std::string revision;   // of the build that ran it
};

// What a shard's config.yaml and axes.txt hold, and the plan they rebuild.
struct ShardInputs {
  std::string config_yaml;
  std::vector<schema::SweepAxis> axes;  // empty for a run
};
// One experiment per grid point (the axes' overrides on the config), or the config alone.
Plan RebuildPlan(const ShardInputs& inputs, const registry::Components& components);

// The files of a shard folder, written through `write(name, text)` (an io::ResultFolder's).
void WriteShardFolder(const std::function<void(const std::string&, const std::string&)>& write, const ShardInfo& info,
                      const ShardInputs& inputs, const Plan& plan, const std::map<int, ChunkResult>& chunks);

// shard.csv, config.yaml and axes.txt, shard.csv last (a folder with it was written whole).
void WriteShardIdentity(const std::function<void(const std::string&, const std::string&)>& write,
                        const ShardInfo& info, const ShardInputs& inputs);

ShardInfo ReadShardInfo(const std::filesystem::path& folder);
ShardInputs ReadShardInputs(const std::filesystem::path& folder);
// The chunks shard.csv says the folder holds, read back and checked against `plan`; a missing or
// broken chunk is an schema::InputError naming its file.
std::map<int, ChunkResult> ReadShardChunks(const std::filesystem::path& folder, const ShardInfo& info,
                                           const Plan& plan);

}  // namespace anchorbench::engine
