#include "monte_carlo_command.hpp"

#include <filesystem>
#include <iostream>
#include <sstream>

#include "anchorbench/config/config_yaml.hpp"
#include "anchorbench/config/load_config.hpp"
#include "anchorbench/report/summary.hpp"
#include "anchorbench/report/sweep_report.hpp"
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

namespace {

engine::ChunkStore::Mode StoreMode(const MonteCarloArgs& args) {
  if (args.resume) return engine::ChunkStore::Mode::kResume;
  return args.overwrite ? engine::ChunkStore::Mode::kOverwrite : engine::ChunkStore::Mode::kFresh;
}

engine::Shard ShardOf(const MonteCarloArgs& args) {
  return args.shard.empty() ? engine::Shard{} : engine::ParseShard(args.shard, "--shard");
}

}  // namespace

std::uintmax_t RunResultBytes(const engine::Plan& plan, const MonteCarloArgs& args) {
  constexpr std::uintmax_t kTables = 1 << 16, kBytesPerAttempt = 360;
  if (!args.shard.empty()) return engine::ChunkBytes(plan, ShardOf(args)) + kTables;
  return kBytesPerAttempt * static_cast<std::uintmax_t>(plan.attempts()) + kTables;
}

PlanOutcome ComputePlan(const MonteCarloArgs& args, const MonteCarloSetup& setup, const PlanJob& job,
                        const AppContext& app, io::ResultFolder& out) {
  const std::optional<engine::Shard> shard = args.shard.empty() ? std::nullopt : std::optional(ShardOf(args));
  engine::ChunkStore store(out.target(), job.plan, StoreMode(args), engine::ChunkBytes(job.plan, ShardOf(args)),
                         InputsOf(args));
  if (store.unreadable() > 0) {  // even with --quiet: the store was damaged
    std::cerr << "anchorbench: note: " << store.folder().string() << ": " << store.unreadable()
              << " chunk file(s) do not read back (first: " << store.first_unreadable() << "); computing them again\n";
  }
  Progress progress(job.command + " " + job.name, args.quiet);
  long long units = 0;
  std::map<int, engine::ChunkResult> chunks =
      engine::RunPlan(job.plan, app.executor,
                    {setup.threads, &store, [&](long long done, long long total) { progress.Update(done, units = total); },
                     shard.value_or(engine::Shard{})});
  PlanOutcome outcome;
  outcome.wall_time_s = progress.elapsed_s();
  progress.Finish(units);
  if (!shard) {
    outcome.experiments = engine::Join(job.plan, chunks);
    return outcome;
  }
  const engine::ShardInfo info{*shard, static_cast<int>(chunks.size()), job.command, job.name, job.plan.identity(),
                             app.revision};
  engine::WriteShardFolder([&](const std::string& name, const std::string& text) { out.Write(name, text); }, info,
                         job.inputs, job.plan, chunks);
  out.Commit();
  store.Remove();
  return outcome;
}

void RemoveStore(const io::ResultFolder& out) {
  std::error_code error;
  std::filesystem::remove_all(engine::ChunkStorePath(out.target()), error);
}

std::string CommitRun(io::ResultFolder& out, const schema::ExperimentConfig& config,
                      const engine::ExperimentAttempts& run, const report::RunInfo& info) {
  const std::vector<schema::RowConfig> rows = schema::RowsOf(config);
  // Every file into the new folder, then the folder in place: an error leaves the old results intact.
  out.Write("attempts.csv", [&](std::ostream& file) { report::WriteAttemptLines(file, run.lines); });
  const std::vector<report::MethodSummary> summaries =
      report::Summarize(run.attempts, rows, config.realizations, config.bootstrap_resamples, config.seed);
  out.Write("summary.csv", [&](std::ostream& file) { report::WriteSummaryCsv(file, summaries, rows); });
  std::ostringstream markdown;
  report::WriteSummaryMarkdown(markdown, summaries, rows, config);
  out.Write("summary.md", markdown.str());
  out.Write("timing.csv", [&](std::ostream& file) { report::WriteTimingCsv(file, summaries, rows); });
  out.Write("manifest.json", report::ManifestJson(config, info));
  out.Commit();
  return markdown.str();
}

std::string CommitSweep(io::ResultFolder& out, const std::string& name, const std::vector<schema::SweepAxis>& axes,
                        const engine::Plan& plan, const std::vector<engine::ExperimentAttempts>& points,
                        report::RunInfo info) {
  const std::vector<schema::SweepPoint> grid = schema::SweepGrid(axes);
  std::vector<report::SweepPointResult> results;
  for (std::size_t p = 0; p < grid.size(); ++p) {
    const schema::ExperimentConfig& config = plan.experiments()[p];
    report::SweepPointResult result{grid[p], plan.rows(static_cast<int>(p)), {}};
    result.summaries =
        report::Summarize(points[p].attempts, result.rows, config.realizations, config.bootstrap_resamples, config.seed);
    results.push_back(std::move(result));
  }
  const schema::ExperimentConfig& first = plan.experiments().front();
  out.Write("sweep.csv", [&](std::ostream& file) { report::WriteSweepCsv(file, axes, results); });
  out.Write("timing.csv", [&](std::ostream& file) { report::WriteSweepTiming(file, axes, results); });
  std::ostringstream md;
  report::WriteSweepMarkdown(md, name, first.realizations, first.seed, axes, results);
  out.Write("sweep.md", md.str());
  info.sweep_axes = schema::DescribeAxes(axes);
  out.Write("manifest.json", report::ManifestJson(first, info));
  out.Commit();
  return md.str();
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
  info.resolved_config_json = config::ToJson(config);
  return info;
}

}  // namespace anchorbench::app
