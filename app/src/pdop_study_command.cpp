#include <iostream>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/studies/pdop_study.hpp"
#include "monte_carlo_command.hpp"

namespace anchorbench::app {

int PdopStudyCommand(const PdopStudyArgs& args, const AppContext& app) {
  schema::ExperimentConfig config = config::LoadConfig(args.config, args.overrides, app.components);
  if (args.realizations) config.realizations = *args.realizations;
  studies::CheckPdopStudy(config, args.every, args.bin_s, args.config);
  const MonteCarloSetup setup = SetUpMonteCarlo(args, config.name);
  // A checkpoint line (~150 bytes) every `every` samples, a few thousand samples per anchor.
  const double anchors = static_cast<double>(config.realizations) * config.scenario.NumAnchors();
  const std::unique_ptr<io::ResultFolder> out =
      OpenResultFolder(args, setup, static_cast<std::uintmax_t>(anchors * 150.0 * 5000.0 / args.every) + (1 << 16));

  Progress progress("pdop-study " + config.name, args.quiet);
  const schema::PdopStudy study = studies::RunPdopStudy(
      config, app.components, args.every, setup.threads,
      {[&](long long done, long long total) { progress.Update(done, total); }, app.stop});
  const double wall_time_s = progress.elapsed_s();
  progress.Finish(config.realizations);
  std::vector<std::string> command_line = CommandLine("", args.overrides);
  command_line.push_back("--every " + std::to_string(args.every));
  command_line.push_back("--bin-s " + io::FormatNumber(args.bin_s));
  const std::string markdown = studies::WritePdopStudyFiles(
      [&](const std::string& name, const std::function<void(std::ostream&)>& write) { out->Write(name, write); },
      config, study, args.every, args.bin_s, RunInfoOf(args, setup, app, config, wall_time_s, command_line));
  out->Commit();
  if (!args.quiet) std::cout << markdown;
  return 0;
}

}  // namespace anchorbench::app
