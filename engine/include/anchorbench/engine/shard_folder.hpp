#pragma once
// A shard folder (`anchorbench run|sweep|navigate|explore --shard I/N`) and what `anchorbench merge`
// reads back:
//   shard.csv      shard,of,chunks,command,name,plan,revision: which share of which plan, by which build;
//   config.yaml    the resolved config (--seed, --set, --realizations applied);
//   axes.txt       a sweep's axes, one KEY=VALUES a line (empty for a run);
//   chunk-*.csv    run, sweep: the shard's chunks (chunk.hpp), named by index;
//   records.csv    a study of record units (navigate, explore, pdop-study; unit_records.hpp): each unit a
//                  block `unit,<index>,<bytes>,<checksum>` and its records' text, as the record
//                  journal keeps them, the checksum bound to the plan's identity.
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
#include "anchorbench/engine/record_journal.hpp"
#include "anchorbench/engine/shard.hpp"

namespace anchorbench::engine {

struct ShardInfo {
  Shard shard;
  int chunks = 0;         // chunks this shard holds (a study of record units: its units)
  std::string command;    // "run", "sweep", or the study of record units ("navigate", "explore")
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

// A study of record units' shard: records.csv of `units` (unit -> its text), then the identity.
inline constexpr const char* kShardRecordsFile = "records.csv";
void WriteShardUnits(const std::function<void(const std::string&, const std::string&)>& write, const ShardInfo& info,
                     const ShardInputs& inputs, const std::map<int, std::string>& units);

struct ShardUnit {
  std::string text;
  UnitPlace place;  // records.csv and its block's line, for messages on its records
};
// The units of a shard's records.csv, each checked against its checksum and the shard (refused,
// as an InputError naming the file and line: a torn or edited file, a unit the shard does not
// hold or holds twice, fewer or more units than shard.csv says, a unit of another plan).
std::map<int, ShardUnit> ReadShardUnits(const std::filesystem::path& folder, const ShardInfo& info, long long units);

ShardInfo ReadShardInfo(const std::filesystem::path& folder);
ShardInputs ReadShardInputs(const std::filesystem::path& folder);
// The chunks shard.csv says the folder holds, read back and checked against `plan`; a missing or
// broken chunk is an schema::InputError naming its file.
std::map<int, ChunkResult> ReadShardChunks(const std::filesystem::path& folder, const ShardInfo& info,
                                           const Plan& plan);

}  // namespace anchorbench::engine
