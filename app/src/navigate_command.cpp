#include <iostream>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/studies/navigation.hpp"
#include "anchorbench/studies/navigation_shard.hpp"
#include "anchorbench/engine/plan.hpp"
#include "anchorbench/engine/record_journal.hpp"
#include "monte_carlo_command.hpp"

namespace anchorbench::app {

int NavigateCommand(const NavigateArgs& args, const AppContext& app) {
  schema::ExperimentConfig config = config::LoadConfig(args.config, args.overrides, app.components);
  if (args.realizations) config.realizations = *args.realizations;
  studies::CheckNavigation(config, app.components);  // before the result folder is claimed
  const std::optional<engine::Shard> shard = ShardOf(args);
  const MonteCarloSetup setup = SetUpMonteCarlo(args, config.name);
  // A line of ~100 bytes per (row, realization, method), and the tables.
  const std::uintmax_t lines = static_cast<std::uintmax_t>(config.realizations) * schema::RowsOf(config).size() *
                               (config.estimator.triggers.size() + 2);
  const std::unique_ptr<io::ResultFolder> out = OpenResultFolder(args, setup, 150 * lines + (1 << 16));

  // Finished units wait in <out>.chunks/'s journal until the results are written: a killed run
  // resumes from it (--resume).
  const engine::Plan plan({config});
  const engine::Shard units_of = shard.value_or(engine::Shard{});
  engine::RecordJournal journal(setup.out, plan.identity() + " shard " + std::to_string(units_of.index) + "/" +
                                               std::to_string(units_of.count),
                                static_cast<long long>(schema::RowsOf(config).size()) * config.realizations,
                                StoreMode(args), InputsOf(args));
  Progress progress("navigate " + config.name, args.quiet);
  const std::vector<studies::NavigationRecord> records =
      studies::RunNavigation(config, app.components, setup.threads, units_of, {nullptr, app.stop}, &journal);
  NoteUnreadable(journal);
  const int units = static_cast<int>(records.size() / (config.estimator.triggers.size() + 2));
  const double wall_time_s = progress.elapsed_s();
  progress.Finish(units);
  if (shard) {
    studies::WriteNavigationShard([&](const std::string& name, const std::string& text) { out->Write(name, text); },
                                 {*shard, units, "navigate", config.name, plan.identity(), app.revision},
                                 {plan.texts().front(), {}}, records);
    out->Commit();
    journal.Remove();
    return 0;
  }
  const std::string markdown = studies::WriteNavigationFiles(
      [&](const std::string& name, const std::function<void(std::ostream&)>& write) { out->Write(name, write); },
      config, records, RunInfoOf(args, setup, app, config, wall_time_s, CommandLine("navigate", args.overrides)));
  out->Commit();
  journal.Remove();
  if (!args.quiet) std::cout << markdown;
  return 0;
}

}  // namespace anchorbench::app
