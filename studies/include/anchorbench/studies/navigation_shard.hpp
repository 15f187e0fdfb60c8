#pragma once
// A navigation study's shard (anchorbench navigate --shard I/N) and its merge (anchorbench merge).
// Shard I of N holds the units u = row * realizations + realization with u % N == I; its folder
// has shard_folder.hpp's shard.csv, config.yaml and axes.txt, and navigation_records.csv: the
// units' records at round-trip precision, so the merged tables are the unsharded run's bytes, each
// line with a checksum of its fields and the plan's identity (a line edited, torn or of another
// run is refused by the merge, as a chunk file's is).

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "anchorbench/studies/navigation.hpp"
#include "anchorbench/engine/shard.hpp"
#include "anchorbench/engine/shard_folder.hpp"

namespace anchorbench::studies {

inline constexpr const char* kNavigationRecordsFile = "navigation_records.csv";

// A shard's records come from RunNavigation(config, components, threads, shard).

// The shard's folder through `write(name, text)`, shard.csv last.
void WriteNavigationShard(const std::function<void(const std::string&, const std::string&)>& write,
                          const engine::ShardInfo& info, const engine::ShardInputs& inputs,
                          const std::vector<NavigationRecord>& records);

// Every shard's records joined in unit order: RunNavigation's. Refuses (InputError naming the file
// and line) a malformed line, one that does not match its checksum, a value no run writes, a unit
// its shard does not hold, or a unit no shard has.
std::vector<NavigationRecord> ReadNavigationShards(const std::vector<std::filesystem::path>& folders,
                                                   const std::vector<engine::ShardInfo>& infos,
                                                   const schema::ExperimentConfig& config);

}  // namespace anchorbench::studies
