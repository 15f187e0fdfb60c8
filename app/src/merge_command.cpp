#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/io/hash.hpp"
#include "anchorbench/io/input_error.hpp"
#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/report/run_outputs.hpp"
#include "anchorbench/report/shard_files.hpp"
#include "anchorbench/report/summary.hpp"
#include "monte_carlo_command.hpp"

namespace anchorbench::app {
namespace {

namespace fs = std::filesystem;
using io::InputError;

// The shards' identities: one run (config and build), every shard of it exactly once.
std::vector<report::ShardInfo> CheckShards(const std::vector<std::string>& folders) {
  std::vector<report::ShardInfo> infos;
  std::map<int, std::string> seen;
  for (const std::string& folder : folders) {
    infos.push_back(report::ReadShardCsv((fs::path(folder) / "shard.csv").string()));
    const report::ShardInfo& info = infos.back();
    const report::ShardInfo& first = infos.front();
    const std::string name = folder + ": shard " + std::to_string(info.shard.index) + "/" +
                             std::to_string(info.shard.count);
    if (info.shard.count != first.shard.count || info.config_hash != first.config_hash ||
        info.config_name != first.config_name) {
      throw InputError(name + " is of another run than " + folders.front() + " (config " + info.config_hash + " vs " +
                       first.config_hash + ", " + std::to_string(info.shard.count) + " vs " +
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
  const std::vector<report::ShardInfo> infos = CheckShards(args.shards);
  const fs::path first_config = fs::path(args.shards.front()) / "config.yaml";
  const std::string config_text = io::ReadWholeFile(first_config.string());
  for (std::size_t s = 0; s < args.shards.size(); ++s) {
    const fs::path path = fs::path(args.shards[s]) / "config.yaml";
    if (io::Fingerprint(io::ReadWholeFile(path.string())) != infos[s].config_hash) {
      throw InputError(path.string() + ": does not match its shard.csv's config_hash (edited after the run?)");
    }
  }
  runner::ExperimentConfig config = config::LoadConfigText(config_text, first_config.string(), {}, app.parts);
  config.name = infos.front().config_name;
  const std::vector<runner::RowConfig> rows = runner::RowsOf(config);
  const int units = static_cast<int>(rows.size()) * config.realizations;

  // Every shard's attempts, placed by unit; each unit from the shard that holds it, whole.
  std::vector<report::AttemptsFile> files;
  std::vector<std::pair<std::size_t, std::size_t>> unit_lines(static_cast<std::size_t>(units), {0, 0});
  std::vector<int> unit_shard(static_cast<std::size_t>(units), -1);
  for (std::size_t s = 0; s < args.shards.size(); ++s) {
    const fs::path folder(args.shards[s]);
    files.push_back(report::ReadAttemptsCsv((folder / "attempts.csv").string(), (folder / "compute_s.csv").string(), rows));
    const report::AttemptsFile& file = files.back();
    if (file.header != files.front().header) throw InputError((folder / "attempts.csv").string() + ": another header");
    int held = 0;
    for (std::size_t i = 0; i < file.attempts.size(); ++i) {
      const runner::Attempt& a = file.attempts[i];
      if (a.realization < 0 || a.realization >= config.realizations) {
        throw InputError((folder / "attempts.csv").string() + ":" + std::to_string(i + 2) + ": realization " +
                         std::to_string(a.realization) + " is not one of the run's");
      }
      const int unit = a.row * config.realizations + a.realization;
      int& owner = unit_shard[static_cast<std::size_t>(unit)];
      auto& [first, last] = unit_lines[static_cast<std::size_t>(unit)];
      if (!infos[s].shard.Holds(unit) || (owner >= 0 && (owner != static_cast<int>(s) || last != i))) {
        throw InputError((folder / "attempts.csv").string() + ":" + std::to_string(i + 2) +
                         ": an attempt of row " + rows[static_cast<std::size_t>(a.row)].name + ", realization " +
                         std::to_string(a.realization) + " that this shard does not hold, or out of order");
      }
      if (owner < 0) {
        owner = static_cast<int>(s);
        first = i;
        ++held;
      }
      last = i + 1;
    }
    if (held != infos[s].units) {
      throw InputError((folder / "attempts.csv").string() + ": " + std::to_string(held) + " units, shard.csv says " +
                       std::to_string(infos[s].units) + " (a shard folder from an unfinished run?)");
    }
  }

  // Whole units: one attempt per anchor and trigger, as a run writes them.
  for (int unit = 0; unit < units; ++unit) {
    const runner::RowConfig& row = rows[static_cast<std::size_t>(unit / config.realizations)];
    const std::size_t expected = static_cast<std::size_t>(row.scenario.NumAnchors()) * row.estimator.triggers.size();
    const auto [first, last] = unit_lines[static_cast<std::size_t>(unit)];
    if (last - first != expected) {
      throw InputError("row " + row.name + ", realization " + std::to_string(unit % config.realizations) + ": " +
                       std::to_string(last - first) + " attempts in the shards, a run writes " +
                       std::to_string(expected) + " (a shard cut short or edited?)");
    }
  }

  io::ResultFolder::Options options;
  options.overwrite = args.overwrite;
  for (const std::string& shard : args.shards) options.inputs.push_back(fs::path(shard) / "attempts.csv");
  io::ResultFolder out(io::ResultFolderPath(args.out, config.name), options);
  std::vector<runner::Attempt> attempts;
  std::ostringstream attempts_csv;
  attempts_csv << files.front().header << '\n';
  for (int unit = 0; unit < units; ++unit) {
    const int owner = unit_shard[static_cast<std::size_t>(unit)];
    if (owner < 0) continue;  // a unit without attempts (a row without anchors)
    const report::AttemptsFile& file = files[static_cast<std::size_t>(owner)];
    const auto [first, last] = unit_lines[static_cast<std::size_t>(unit)];
    for (std::size_t i = first; i < last; ++i) {
      attempts.push_back(file.attempts[i]);
      attempts_csv << file.lines[i] << '\n';
    }
  }
  out.Write("attempts.csv", attempts_csv.str());
  const std::string markdown = WriteRunTables(out, attempts, rows, config);
  report::RunInfo info;
  info.config_path = first_config.string();
  info.revision = infos.front().revision;
  for (const std::string& shard : args.shards) info.command_line.push_back("merge " + shard);
  info.resolved_config_json = config::ToJson(config);
  out.Write("manifest.json", report::ManifestJson(config, info));
  out.Commit();
  if (!args.quiet) std::cout << markdown;
  return 0;
}

}  // namespace anchorbench::app
