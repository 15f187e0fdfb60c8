#include <iostream>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/studies/exploration.hpp"
#include "anchorbench/engine/plan.hpp"
#include "anchorbench/engine/record_journal.hpp"
#include "monte_carlo_command.hpp"

namespace anchorbench::app {

int ExploreCommand(const ExploreArgs& args, const AppContext& app) {
  schema::ExperimentConfig config = config::LoadConfig(args.config, args.overrides, app.components);
  if (args.realizations) config.realizations = *args.realizations;
  studies::CheckExploration(config, app.components);  // before the result folder is claimed
  const MonteCarloSetup setup = SetUpMonteCarlo(args, config.name);
  // A line of ~100 bytes per (row, realization, policy), and the tables.
  const std::uintmax_t lines = static_cast<std::uintmax_t>(config.realizations) * schema::RowsOf(config).size() *
                               config.exploration->policies.size();
  const std::unique_ptr<io::ResultFolder> out = OpenResultFolder(args, setup, 120 * lines + (1 << 16));

  // Finished units wait in <out>.chunks/'s journal until the results are written: a killed run
  // resumes from it (--resume).
  const engine::Plan plan({config});
  engine::RecordJournal journal(setup.out, plan.identity() + " explore",
                                static_cast<long long>(schema::RowsOf(config).size()) * config.realizations,
                                StoreMode(args), InputsOf(args));
  Progress progress("explore " + config.name, args.quiet);
  const std::vector<studies::ExplorationRecord> records = studies::RunExploration(
      config, app.components, setup.threads,
      {[&](long long done, long long total) { progress.Update(done, total); }, app.stop}, &journal);
  NoteUnreadable(journal);
  const double wall_time_s = progress.elapsed_s();
  progress.Finish(static_cast<long long>(records.size() / config.exploration->policies.size()));
  const std::string markdown = studies::WriteExplorationFiles(
      [&](const std::string& name, const std::function<void(std::ostream&)>& write) { out->Write(name, write); },
      config, records, RunInfoOf(args, setup, app, config, wall_time_s, CommandLine("explore", args.overrides)));
  out->Commit();
  journal.Remove();
  if (!args.quiet) std::cout << markdown;
  return 0;
}

}  // namespace anchorbench::app
