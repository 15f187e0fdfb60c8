#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/engine/commit.hpp"
#include "anchorbench/engine/shard_folder.hpp"
#include "anchorbench/studies/record_study.hpp"
#include "monte_carlo_command.hpp"

namespace anchorbench::app {
namespace {

namespace fs = std::filesystem;
using schema::InputError;

// The shards' identities: one plan (command, config and build), every shard of it exactly once.
std::vector<engine::ShardInfo> CheckShards(const std::vector<std::string>& folders) {
  std::vector<engine::ShardInfo> infos;
  std::map<int, std::string> seen;
  for (const std::string& folder : folders) {
    infos.push_back(engine::ReadShardInfo(folder));
    const engine::ShardInfo& info = infos.back();
    const engine::ShardInfo& first = infos.front();
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

// Every folder's config.yaml and axes.txt, each the first folder's (a shard of one run holds the
// same): the plan they rebuild, checked against shard.csv's.
engine::Plan CheckInputs(const std::vector<std::string>& folders, const engine::ShardInfo& info,
                       const registry::Components& components, engine::ShardInputs& inputs) {
  const fs::path first(folders.front());
  inputs = engine::ReadShardInputs(first);
  const engine::Plan plan = engine::RebuildPlan(inputs, components);
  if (plan.identity() != info.plan) {
    throw InputError((first / "config.yaml").string() + ": with axes.txt gives plan " + plan.identity() +
                     ", shard.csv says " + info.plan + " (edited after the run?)");
  }
  for (std::size_t s = 1; s < folders.size(); ++s) {
    const engine::ShardInputs other = engine::ReadShardInputs(folders[s]);
    if (other.config_yaml != inputs.config_yaml || schema::DescribeAxes(other.axes) != schema::DescribeAxes(inputs.axes)) {
      throw InputError((fs::path(folders[s]) / "config.yaml").string() + ": with axes.txt differs from " +
                       (first / "config.yaml").string() + "'s: shards of one run hold the same (edited after the run?)");
    }
  }
  return plan;
}

// The merged results' folder, claimed before any chunk is read: about the size of the chunks.
std::unique_ptr<io::ResultFolder> OpenMerged(const MergeArgs& args, const std::string& name) {
  io::ResultFolder::Options options;
  options.overwrite = args.overwrite;
  options.expected_bytes = 1 << 16;
  std::error_code error;
  for (const std::string& shard : args.shards) {
    options.inputs.push_back(fs::path(shard) / "shard.csv");
    options.input_folders.emplace_back(shard);
    for (const fs::directory_entry& entry : fs::directory_iterator(shard, error)) {
      if (entry.is_regular_file(error)) options.expected_bytes += entry.file_size(error);
    }
  }
  return std::make_unique<io::ResultFolder>(io::ResultFolderPath(args.out, name), options);
}

// The merged manifest's record: the shards' config, build and folders.
report::RunInfo MergedInfo(const MergeArgs& args, const engine::ShardInfo& first, const engine::ShardInputs& inputs,
                           const AppContext& app) {
  report::RunInfo info;
  info.config_path = (fs::path(args.shards.front()) / "config.yaml").string();
  info.revision = first.revision;
  for (const std::string& shard : args.shards) info.command_line.push_back("merge " + shard);
  info.resolved_config = config::ToJson(config::LoadConfigText(inputs.config_yaml, "config.yaml", {}, app.components));
  return info;
}

// Every one of a study's `units`, each from the shard that holds it (engine::ReadShardUnits): unit
// -> its text, and where it was read.
std::map<int, engine::ShardUnit> ReadUnits(const MergeArgs& args, const std::vector<engine::ShardInfo>& infos,
                                           int units, int realizations) {
  std::map<int, engine::ShardUnit> read;
  for (std::size_t s = 0; s < args.shards.size(); ++s) read.merge(engine::ReadShardUnits(args.shards[s], infos[s], units));
  for (int unit = 0; unit < units; ++unit) {
    if (read.count(unit) == 0) {
      throw InputError("row " + std::to_string(unit / realizations) + ", realization " +
                       std::to_string(unit % realizations) + ": no shard holds its records (edited after the run?)");
    }
  }
  return read;
}

// A study of record units' shards (navigate, explore, pdop-study) into its results: the unsharded run's bytes.
int MergeUnits(const studies::RecordStudy& study, const MergeArgs& args, const std::vector<engine::ShardInfo>& infos,
               const engine::ShardInputs& inputs, const engine::Plan& plan, const AppContext& app,
               io::ResultFolder& out) {
  schema::ExperimentConfig config = plan.experiments().front();
  config.name = infos.front().name;
  study.check(config, app.components);
  std::map<int, std::string> texts;
  std::map<int, engine::UnitPlace> places;
  for (auto& [unit, read] : ReadUnits(args, infos, study.units(config, app.components), config.realizations)) {
    texts.emplace(unit, std::move(read.text));
    places.emplace(unit, std::move(read.place));
  }
  report::RunInfo info = MergedInfo(args, infos.front(), inputs, app);
  info.command_line.insert(info.command_line.begin(), study.command);
  const std::string markdown = study.write(
      [&](const std::string& name, const std::function<void(std::ostream&)>& write) { out.Write(name, write); }, config,
      app.components, texts, [&places](int unit) { return places.at(unit); }, info);
  out.Commit();
  if (!args.quiet) std::cout << markdown;
  return 0;
}

}  // namespace

int MergeCommand(const MergeArgs& args, const AppContext& app) {
  const std::vector<engine::ShardInfo> infos = CheckShards(args.shards);
  engine::ShardInputs inputs;
  const engine::Plan plan = CheckInputs(args.shards, infos.front(), app.components, inputs);
  const std::string& command = infos.front().command;
  const studies::RecordStudy* study = studies::FindRecordStudy(command);
  if (command != "run" && command != "sweep" && !study) {
    std::string known = "run, sweep";
    for (const studies::RecordStudy& s : studies::RecordStudies()) known += ", " + s.command;
    throw InputError((fs::path(args.shards.front()) / "shard.csv").string() + ": command '" + command + "': " + known);
  }
  const std::unique_ptr<io::ResultFolder> out = OpenMerged(args, infos.front().name);
  if (study) return MergeUnits(*study, args, infos, inputs, plan, app, *out);
  std::map<int, engine::ChunkResult> chunks;
  for (std::size_t s = 0; s < args.shards.size(); ++s) {
    chunks.merge(engine::ReadShardChunks(args.shards[s], infos[s], plan));
  }

  const std::vector<engine::ExperimentAttempts> joined = engine::Join(plan, chunks);
  const report::RunInfo info = MergedInfo(args, infos.front(), inputs, app);
  std::string markdown;
  if (infos.front().command == "run") {
    schema::ExperimentConfig config = plan.experiments().front();
    config.name = infos.front().name;
    markdown = engine::CommitRun(*out, config, joined.front(), info);
  } else {
    markdown = engine::CommitSweep(*out, infos.front().name, inputs.axes, plan, joined, info);
  }
  if (!args.quiet) std::cout << markdown;
  return 0;
}

}  // namespace anchorbench::app
