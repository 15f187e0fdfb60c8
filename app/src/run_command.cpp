#include <iostream>
#include <sstream>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/hash.hpp"
#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/report/run_outputs.hpp"
#include "anchorbench/report/shard_files.hpp"
#include "anchorbench/report/summary.hpp"
#include "anchorbench/runner/monte_carlo.hpp"
#include "anchorbench/work/run_plan.hpp"
#include "anchorbench/io/input_error.hpp"
#include "monte_carlo_command.hpp"

namespace anchorbench::app {
namespace {

// attempts.csv is ~200 bytes a row; the rest of the folder is small.
std::uintmax_t ExpectedBytes(const runner::ExperimentConfig& config) {
  std::uintmax_t attempts = 0;
  for (const runner::RowConfig& row : runner::RowsOf(config)) {
    attempts += static_cast<std::uintmax_t>(config.realizations) * static_cast<std::uintmax_t>(row.scenario.NumAnchors()) *
                row.estimator.triggers.size();
  }
  return 200 * attempts + (1 << 16);
}

}  // namespace

namespace {

// A shard's attempts and what merge needs to check and join them; no summary.
int RunShard(const RunArgs& args, const AppContext& app, const runner::ExperimentConfig& config,
             const runner::Shard& shard) {
  const std::vector<runner::RowConfig> rows = runner::RowsOf(config);
  const MonteCarloSetup setup = SetUpMonteCarlo(args, config.name);
  const std::unique_ptr<io::ResultFolder> out = OpenResultFolder(args, setup, ExpectedBytes(config));
  Progress progress("run " + config.name, args.quiet);
  const std::vector<runner::Attempt> attempts = runner::RunMonteCarlo(
      config, app.parts, {setup.threads, [&](int done, int total) { progress.Update(done, total); }, shard});
  const int units = static_cast<int>(rows.size()) * config.realizations;
  progress.Finish(shard.UnitsOf(units));
  const std::string resolved = config::ToYaml(config);
  out->Write("attempts.csv", [&](std::ostream& file) { report::WriteAttempts(file, attempts, rows); });
  out->Write("compute_s.csv", [&](std::ostream& file) { report::WriteComputeCsv(file, attempts); });
  out->Write("config.yaml", resolved);
  out->Write("shard.csv", [&](std::ostream& file) {
    report::WriteShardCsv(file, {shard, shard.UnitsOf(units), config.name, io::Fingerprint(resolved), app.revision});
  });
  out->Commit();
  return 0;
}

}  // namespace

int RunCommand(const RunArgs& args, const AppContext& app) {
  runner::ExperimentConfig config = config::LoadConfig(args.config, args.overrides, app.parts);
  if (args.seed) config.seed = *args.seed;
  if (args.realizations) config.realizations = *args.realizations;
  const std::vector<runner::RowConfig> rows = runner::RowsOf(config);
  runner::CheckWork(config);
  runner::CheckRows(rows, app.parts);
  if (!args.shard.empty()) {
    if (args.resume) throw io::InputError("--resume with --shard: a shard is redone whole (rerun the missing ones)");
    return RunShard(args, app, config, runner::ParseShard(args.shard, "--shard"));
  }
  const MonteCarloSetup setup = SetUpMonteCarlo(args, config.name);
  const std::unique_ptr<io::ResultFolder> out = OpenResultFolder(args, setup, ExpectedBytes(config));
  const work::Plan plan({config});
  work::ChunkStore store(setup.out, plan, StoreMode(args));

  Progress progress("run " + config.name, args.quiet);
  work::ExperimentAttempts run = std::move(work::RunPlan(plan, app.executor, {setup.threads, &store, [&](long long done, long long total) {
    progress.Update(done, total);
  }}).front());
  const double wall_time_s = progress.elapsed_s();
  progress.Finish(plan.units());
  std::vector<std::string> command_line;
  if (args.seed) command_line.push_back("--seed " + std::to_string(*args.seed));
  for (const std::string& assignment : args.overrides) command_line.push_back("--set " + assignment);
  // Every file into the new folder, then the folder in place: an error leaves the old results intact.
  out->Write("attempts.csv", [&](std::ostream& file) { report::WriteAttemptLines(file, run.lines); });
  const std::string markdown = WriteRunTables(*out, run.attempts, rows, config);
  out->Write("manifest.json",
             report::ManifestJson(config, RunInfoOf(args, setup, app, config, wall_time_s, command_line)));
  out->Commit();
  store.Remove();
  if (!args.quiet) std::cout << markdown;
  return 0;
}

}  // namespace anchorbench::app
