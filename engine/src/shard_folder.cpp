#include "anchorbench/engine/shard_folder.hpp"

#include <fstream>
#include <sstream>

#include "anchorbench/config/load_config.hpp"
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
  if (info.command != "run" && info.command != "sweep" && info.command != "navigate") {
    csv.Fail("command '" + info.command + "': run, sweep or navigate");
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
