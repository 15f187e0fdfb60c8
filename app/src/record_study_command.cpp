#include <iostream>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/engine/plan.hpp"
#include "anchorbench/engine/record_journal.hpp"
#include "anchorbench/engine/shard_folder.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "monte_carlo_command.hpp"

namespace anchorbench::app {

RecordStudyArgs PdopStudyArgs::WithSettings() const {
  RecordStudyArgs args = *this;
  if (every) args.overrides.push_back("pdop_study.every=" + std::to_string(*every));
  if (bin_s) args.overrides.push_back("pdop_study.bin_s=" + io::FormatNumber(*bin_s));
  return args;
}

int RecordStudyCommand(const std::string& command, const RecordStudyArgs& args, const AppContext& app) {
  const studies::RecordStudy* study = studies::FindRecordStudy(command);
  if (!study) throw schema::InputError("'" + command + "' is not a study of record units");
  schema::ExperimentConfig config = config::LoadConfig(args.config, args.overrides, app.components);
  if (args.realizations) config.realizations = *args.realizations;
  study->check(config, app.components);  // before the result folder is claimed
  const std::optional<engine::Shard> shard = ShardOf(args);
  const MonteCarloSetup setup = SetUpMonteCarlo(args, config.name);
  const std::unique_ptr<io::ResultFolder> out = OpenResultFolder(args, setup, study->result_bytes(config));

  // Finished units wait in <out>.chunks/'s journal until the results are written: a killed run
  // resumes from it (--resume).
  const engine::Plan plan({config});
  const engine::Shard units_of = shard.value_or(engine::Shard{});
  engine::RecordJournal journal(setup.out,
                                plan.identity() + " " + command + " shard " + std::to_string(units_of.index) + "/" +
                                    std::to_string(units_of.count),
                                study->units(config, app.components),
                                StoreMode(args), InputsOf(args));
  Progress progress(command + " " + config.name, args.quiet);
  const std::map<int, std::string> units = study->run(
      config, app.components, {&app.executor, command, &plan, setup.threads}, units_of,
      {[&](long long done, long long total) { progress.Update(done, total); }, app.stop}, &journal);
  NoteUnreadable(journal);
  const double wall_time_s = progress.elapsed_s();
  progress.Finish(static_cast<long long>(units.size()));
  std::string markdown;
  if (shard) {
    engine::WriteShardUnits([&](const std::string& name, const std::string& text) { out->Write(name, text); },
                            {*shard, static_cast<int>(units.size()), command, config.name, plan.identity(),
                             app.revision},
                            {plan.texts().front(), {}}, units);
  } else {
    markdown = study->write(
        [&](const std::string& name, const std::function<void(std::ostream&)>& write) { out->Write(name, write); },
        config, app.components, units, [&journal](int unit) { return journal.PlaceOf(unit); },
        RunInfoOf(args, setup, app, config, wall_time_s, CommandLine(command, args.overrides)));
  }
  out->Commit();
  journal.Remove();
  if (!args.quiet) std::cout << markdown;
  return 0;
}

}  // namespace anchorbench::app
