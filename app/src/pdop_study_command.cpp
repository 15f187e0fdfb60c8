#include <iostream>
#include <sstream>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/atomic_file.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/io/input_error.hpp"
#include "anchorbench/report/pdop_study_report.hpp"
#include "anchorbench/runner/pdop_study.hpp"
#include "monte_carlo_command.hpp"

namespace anchorbench::app {

int PdopStudyCommand(const PdopStudyArgs& args, const AppContext& app) {
  runner::ExperimentConfig config = config::LoadConfig(args.config, {}, app.parts);
  if (args.realizations) config.realizations = *args.realizations;
  if (args.every < 1) throw io::InputError("--every must be >= 1");
  if (!(args.bin_s > 0.0)) throw io::InputError("--bin-s must be > 0");
  const MonteCarloSetup setup = SetUpMonteCarlo(args, config.name);

  Progress progress("pdop-study " + config.name, args.quiet);
  const runner::PdopStudy study = runner::RunPdopStudy(config, app.parts, args.every, setup.threads);
  const double wall_time_s = progress.elapsed_s();
  progress.Finish(config.realizations);

  io::AtomicFile trace(setup.out / "pdop_trace.csv");
  report::WritePdopTrace(trace.stream(), study.checkpoints);
  std::ostringstream md;
  report::WritePdopStudyMarkdown(md, config, study, args.every, args.bin_s);
  io::AtomicFile summary(setup.out / "pdop_study.md");
  summary.stream() << md.str();
  const std::vector<std::string> command_line = {"--every " + std::to_string(args.every),
                                                 "--bin-s " + io::FormatNumber(args.bin_s)};
  io::AtomicFile manifest(setup.out / "manifest.json");
  manifest.stream() << report::ManifestJson(config, RunInfoOf(args, setup, app, config, wall_time_s, command_line));
  for (io::AtomicFile* file : {&trace, &summary, &manifest}) file->Commit();
  if (!args.quiet) std::cout << md.str();
  return 0;
}

}  // namespace anchorbench::app
