#include <iostream>
#include <sstream>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/report/pdop_study_report.hpp"
#include "anchorbench/studies/pdop_study.hpp"
#include "monte_carlo_command.hpp"

namespace anchorbench::app {

int PdopStudyCommand(const PdopStudyArgs& args, const AppContext& app) {
  schema::ExperimentConfig config = config::LoadConfig(args.config, args.overrides, app.components);
  if (args.realizations) config.realizations = *args.realizations;
  if (args.every < 1 || args.every > 1000000) throw schema::InputError("--every: must be in [1, 1000000]");
  // The summary's bins cover Fig. 7's first 120 s: at least 0.01 s (12,000 bins), at most all of it.
  if (!(args.bin_s >= 0.01 && args.bin_s <= 120.0)) throw schema::InputError("--bin-s: must be in [0.01, 120] seconds");
  const double anchors = static_cast<double>(config.realizations) * config.scenario.NumAnchors();
  if (anchors > 1e6) throw schema::InputError(args.config + ": realizations x anchors above 1e6 for a PDOP study");
  const MonteCarloSetup setup = SetUpMonteCarlo(args, config.name);
  // A checkpoint line (~150 bytes) every `every` samples, a few thousand samples per anchor.
  const std::unique_ptr<io::ResultFolder> out =
      OpenResultFolder(args, setup, static_cast<std::uintmax_t>(anchors * 150.0 * 5000.0 / args.every) + (1 << 16));

  Progress progress("pdop-study " + config.name, args.quiet);
  const schema::PdopStudy study = studies::RunPdopStudy(
      config, app.components, args.every, setup.threads,
      {[&](long long done, long long total) { progress.Update(done, total); }, app.stop});
  const double wall_time_s = progress.elapsed_s();
  progress.Finish(config.realizations);

  out->Write("pdop_trace.csv", [&](std::ostream& file) { report::WritePdopTrace(file, study.checkpoints); });
  std::ostringstream md;
  report::WritePdopStudyMarkdown(md, config, study, args.every, args.bin_s);
  out->Write("pdop_study.md", md.str());
  std::vector<std::string> command_line = CommandLine("", args.overrides);
  command_line.push_back("--every " + std::to_string(args.every));
  command_line.push_back("--bin-s " + io::FormatNumber(args.bin_s));
  out->Write("manifest.json",
             report::ManifestJson(config, RunInfoOf(args, setup, app, config, wall_time_s, command_line)));
  out->Commit();
  if (!args.quiet) std::cout << md.str();
  return 0;
}

}  // namespace anchorbench::app
