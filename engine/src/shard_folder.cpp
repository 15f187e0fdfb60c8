#include "anchorbench/engine/shard_folder.hpp"

#include <fstream>
#include <sstream>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/engine/block_log.hpp"
#include "anchorbench/engine/record_journal.hpp"
#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::engine {
namespace fs = std::filesystem;

Plan RebuildPlan(const ShardInputs& inputs, const registry::Components& components) {
  std::vector<schema::ExperimentConfig> experiments;
  if (inputs.axes.empty()) {
    experiments.push_back(config::LoadConfigText(inputs.config_yaml, "config.yaml", {}, components));
  } else {
    for (const schema::SweepPoint& point : schema::SweepGrid(inputs.axes)) {
      experiments.push_back(config::LoadConfigText(inputs.config_yaml, "config.yaml", point.overrides, components));
    }
  }
  return Plan(std::move(experiments));
}

void WriteShardFolder(const std::function<void(const std::string&, const std::string&)>& write, const ShardInfo& info,
                      const ShardInputs& inputs, const Plan& plan, const std::map<int, ChunkResult>& chunks) {
  for (const auto& [chunk, result] : chunks) write(ChunkFileName(chunk), ChunkText(plan, chunk, result));
  WriteShardIdentity(write, info, inputs);
}

void WriteShardIdentity(const std::function<void(const std::string&, const std::string&)>& write,
                        const ShardInfo& info, const ShardInputs& inputs) {
  write("config.yaml", inputs.config_yaml);
  std::string axes;
  for (const std::string& axis : schema::DescribeAxes(inputs.axes)) axes += axis + '\n';
  write("axes.txt", axes);
  std::ostringstream csv;
  csv << "shard,of,chunks,command,name,plan,revision\n"
      << info.shard.index << ',' << info.shard.count << ',' << info.chunks << ',' << info.command << ',' << info.name
      << ',' << info.plan << ',' << info.revision << '\n';
  write("shard.csv", csv.str());  // last: a folder with shard.csv was written whole
}

void WriteShardUnits(const std::function<void(const std::string&, const std::string&)>& write, const ShardInfo& info,
                     const ShardInputs& inputs, const std::map<int, std::string>& units) {
  std::string blocks;
  for (const auto& [unit, text] : units) {
    blocks += BlockText(kUnitBlockKind, unit, UnitChecksum(info.plan, unit, text), text);
  }
  write(kShardRecordsFile, blocks);
  WriteShardIdentity(write, info, inputs);
}

std::map<int, ShardUnit> ReadShardUnits(const fs::path& folder, const ShardInfo& info, long long units) {
  const fs::path path = folder / kShardRecordsFile;
  if (!fs::exists(path)) throw schema::InputError(path.string() + ": missing (a folder edited after the run?)");
  std::map<int, ShardUnit> read;
  const std::string damage = ReadBlockLog(path, kUnitBlockKind, [&](LoggedBlock&& block) {
    const UnitPlace place{path.string(), block.line};
    const std::string what = place.where() + ": unit " + std::to_string(block.key);
    if (block.key >= units || !info.shard.Holds(static_cast<int>(block.key))) {
      throw schema::InputError(what + " is not a unit of shard " + std::to_string(info.shard.index) + "/" +
                               std::to_string(info.shard.count) + " (edited after the run?)");
    }
    if (block.tag != UnitChecksum(info.plan, block.key, block.text)) {
      throw schema::InputError(what + " does not match its checksum (edited after the run, or another run's?)");
    }
    if (!read.emplace(static_cast<int>(block.key), ShardUnit{std::move(block.text), place}).second) {
      throw schema::InputError(what + " is there twice (edited after the run?)");
    }
  });
  if (!damage.empty()) throw schema::InputError(damage);
  if (static_cast<long long>(read.size()) != info.chunks) {
    throw schema::InputError(path.string() + ": holds " + std::to_string(read.size()) + " units, " +
                             (folder / "shard.csv").string() + " says " + std::to_string(info.chunks) +
                             " (edited after the run?)");
  }
  return read;
}

ShardInfo ReadShardInfo(const fs::path& folder) {
  const std::string path = (folder / "shard.csv").string();
  std::ifstream in = io::OpenForReading(path);
  io::CsvReader csv(in, path);
  if (!csv.Next()) csv.Fail("no shard line");
  ShardInfo info;
  info.shard.index = csv.Integer(csv.Column({"shard"}));
  info.shard.count = csv.Integer(csv.Column({"of"}));
  info.chunks = csv.Integer(csv.Column({"chunks"}));
  info.command = std::string(csv.Text(csv.Column({"command"})));
  info.name = std::string(csv.Text(csv.Column({"name"})));
  info.plan = std::string(csv.Text(csv.Column({"plan"})));
  info.revision = std::string(csv.Text(csv.Column({"revision"})));
  if (info.shard.count < 1 || info.shard.index < 0 || info.shard.index >= info.shard.count) {
    csv.Fail("shard " + std::to_string(info.shard.index) + " of " + std::to_string(info.shard.count) + " is not a shard");
  }
  return info;
}

ShardInputs ReadShardInputs(const fs::path& folder) {
  ShardInputs inputs;
  inputs.config_yaml = io::ReadWholeFile((folder / "config.yaml").string());
  std::istringstream axes(io::ReadWholeFile((folder / "axes.txt").string()));
  for (std::string line; std::getline(axes, line);) inputs.axes.push_back(schema::ParseSweepAssignment(line));
  return inputs;
}

std::map<int, ChunkResult> ReadShardChunks(const fs::path& folder, const ShardInfo& info, const Plan& plan) {
  std::map<int, ChunkResult> chunks;
  for (int chunk = 0; chunk < static_cast<int>(plan.chunks().size()); ++chunk) {
    if (!info.shard.Holds(chunk)) continue;
    const fs::path path = folder / ChunkFileName(chunk);
    if (!fs::exists(path)) {
      throw schema::InputError(path.string() + ": missing; shard " + std::to_string(info.shard.index) + "/" +
                           std::to_string(info.shard.count) + " holds it (a folder edited after the run?)");
    }
    chunks.emplace(chunk, ReadChunkFile(plan, chunk, path.string()));
  }
  if (static_cast<int>(chunks.size()) != info.chunks) {
    throw schema::InputError((folder / "shard.csv").string() + ": says " + std::to_string(info.chunks) +
                         " chunks, the plan gives this shard " + std::to_string(chunks.size()));
  }
  return chunks;
}

}  // namespace anchorbench::engine
