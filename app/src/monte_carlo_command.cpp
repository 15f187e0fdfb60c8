#include "monte_carlo_command.hpp"

#include <filesystem>
#include <iostream>

#include "anchorbench/config/config_yaml.hpp"
#include "anchorbench/config/load_config.hpp"
#include "anchorbench/engine/monte_carlo.hpp"

namespace anchorbench::app {

MonteCarloSetup SetUpMonteCarlo(const MonteCarloArgs& args, const std::string& config_name) {
  MonteCarloSetup setup;
  setup.threads = engine::ResolveThreads(args.threads);
  setup.out = io::ResultFolderPath(args.out, config_name);
  return setup;
}

std::vector<std::filesystem::path> InputsOf(const MonteCarloArgs& args) {
  std::vector<std::filesystem::path> inputs;
  for (const std::string& file : config::ConfigFiles(args.config)) inputs.emplace_back(file);
  return inputs;
}

std::unique_ptr<io::ResultFolder> OpenResultFolder(const MonteCarloArgs& args, const MonteCarloSetup& setup,
                                                  std::uintmax_t expected_bytes) {
  io::ResultFolder::Options options;
  options.overwrite = args.overwrite;
  options.expected_bytes = expected_bytes;
  options.inputs = InputsOf(args);
  return std::make_unique<io::ResultFolder>(setup.out, options);
}

engine::ChunkStore::Mode StoreMode(const MonteCarloArgs& args) {
  if (args.resume) return engine::ChunkStore::Mode::kResume;
  return args.overwrite ? engine::ChunkStore::Mode::kOverwrite : engine::ChunkStore::Mode::kFresh;
}

void NoteUnreadable(const engine::RecordJournal& journal) {
  if (journal.unreadable() == 0) return;
  std::cerr << "anchorbench: note: " << journal.folder().string() << ": " << journal.unreadable()
            << " unit(s) did not read back (first: " << journal.first_unreadable() << "); computed again\n";
}

std::optional<engine::Shard> ShardOf(const MonteCarloArgs& args) {
  if (args.shard.empty()) return std::nullopt;
  return engine::ParseShard(args.shard, "--shard");
}

PlanOutcome ComputePlan(const MonteCarloArgs& args, const MonteCarloSetup& setup, const engine::Job& job,
                        const AppContext& app, io::ResultFolder& out) {
  Progress progress(job.command + " " + job.name, args.quiet);
  long long units = 0;
  engine::JobOptions options;
  options.threads = setup.threads;
  options.store_mode = StoreMode(args);
  options.shard = ShardOf(args);
  options.inputs = InputsOf(args);
  options.progress = [&](long long done, long long total) { progress.Update(done, units = total); };
  options.note = [](const std::string& note) { std::cerr << "anchorbench: note: " << note << "\n"; };
  PlanOutcome outcome;
  outcome.experiments = engine::ComputeJob(job, app.executor, options, out);
  outcome.wall_time_s = progress.elapsed_s();
  progress.Finish(units);
  return outcome;
}

std::vector<std::string> CommandLine(const std::string& command, const std::vector<std::string>& overrides) {
  std::vector<std::string> words;
  if (!command.empty()) words.push_back(command);
  for (const std::string& assignment : overrides) words.push_back("--set " + assignment);
  return words;
}

report::RunInfo RunInfoOf(const MonteCarloArgs& args, const MonteCarloSetup& setup, const AppContext& app,
                          const schema::ExperimentConfig& config, double wall_time_s,
                          std::vector<std::string> more_command_line) {
  report::RunInfo info;
  info.config_path = args.config;
  info.revision = app.revision;
  info.threads = setup.threads;
  info.wall_time_s = wall_time_s;
  if (args.realizations) info.command_line.push_back("--realizations " + std::to_string(*args.realizations));
  for (std::string& item : more_command_line) info.command_line.push_back(std::move(item));
  info.resolved_config = config::ToJson(config);
  return info;
}

}  // namespace anchorbench::app
