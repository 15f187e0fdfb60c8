#include <filesystem>
#include <iostream>
#include <map>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/input_error.hpp"
#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/work/shard_folder.hpp"
#include "monte_carlo_command.hpp"

namespace anchorbench::app {
namespace {

namespace fs = std::filesystem;
using io::InputError;

// The shards' identities: one plan (command, config and build), every shard of it exactly once.
std::vector<work::ShardInfo> CheckShards(const std::vector<std::string>& folders) {
  std::vector<work::ShardInfo> infos;
  std::map<int, std::string> seen;
  for (const std::string& folder : folders) {
    infos.push_back(work::ReadShardInfo(folder));
    const work::ShardInfo& info = infos.back();
    const work::ShardInfo& first = infos.front();
    const std::string name = folder + ": shard " + std::to_string(info.shard.index) + "/" +
                             std::to_string(info.shard.count);
    if (info.shard.count != first.shard.count || info.plan != first.plan || info.command != first.command ||
        info.name != first.name) {
      throw InputError(name + " is of another run than " + folders.front() + " (plan " + info.plan + " vs " +
                       first.plan + ", " + std::to_string(info.shard.count) + " vs " +
                       std::to_string(first.shard.count) + " shards)");
    }
    if (info.revision != first.revision) {
      throw InputError(name + " was run by build " + info.revision + ", " + folders.front() + " by " + first.revision +
                       ": shards of one run need one build");
    }
    if (!seen.emplace(info.shard.index, folder).second) {
      throw InputError(name + " is given twice (also " + seen[info.shard.index] + ")");
    }
  }
  for (int i = 0; i < infos.front().shard.count; ++i) {
    if (!seen.count(i)) {
      throw InputError("shard " + std::to_string(i) + "/" + std::to_string(infos.front().shard.count) +
                       " is missing: every shard of the run is needed");
    }
  }
  return infos;
}

}  // namespace

int MergeCommand(const MergeArgs& args, const AppContext& app) {
  const std::vector<work::ShardInfo> infos = CheckShards(args.shards);
  const fs::path first(args.shards.front());
  const work::ShardInputs inputs = work::ReadShardInputs(first);
  const work::Plan plan = work::RebuildPlan(inputs, app.parts);
  if (plan.identity() != infos.front().plan) {
    throw InputError((first / "config.yaml").string() + ": with axes.txt gives plan " + plan.identity() +
                     ", shard.csv says " + infos.front().plan + " (edited after the run?)");
  }
  std::map<int, work::ChunkResult> chunks;
  for (std::size_t s = 0; s < args.shards.size(); ++s) {
    chunks.merge(work::ReadShardChunks(args.shards[s], infos[s], plan));
  }

  io::ResultFolder::Options options;
  options.overwrite = args.overwrite;
  for (const std::string& shard : args.shards) options.inputs.push_back(fs::path(shard) / "shard.csv");
  io::ResultFolder out(io::ResultFolderPath(args.out, infos.front().name), options);
  const std::vector<work::ExperimentAttempts> joined = work::Join(plan, chunks);
  report::RunInfo info;
  info.config_path = (first / "config.yaml").string();
  info.revision = infos.front().revision;
  for (const std::string& shard : args.shards) info.command_line.push_back("merge " + shard);
  info.resolved_config_json = config::ToJson(config::LoadConfigText(inputs.config_yaml, "config.yaml", {}, app.parts));
  std::string markdown;
  if (infos.front().command == "run") {
    runner::ExperimentConfig config = plan.experiments().front();
    config.name = infos.front().name;
    markdown = CommitRun(out, config, joined.front(), info);
  } else {
    markdown = CommitSweep(out, infos.front().name, inputs.axes, plan, joined, info);
  }
  if (!args.quiet) std::cout << markdown;
  return 0;
}

}  // namespace anchorbench::app
