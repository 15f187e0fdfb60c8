#include <filesystem>
#include <iostream>
#include <sstream>

#include "anchorbench/studies/calibration_report.hpp"
#include "anchorbench/studies/calibration_runs.hpp"
#include "anchorbench/studies/evaluation_log.hpp"
#include "anchorbench/studies/fit.hpp"
#include "anchorbench/config/load_calibration.hpp"
#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/atomic_file.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/report/paper_cells.hpp"
#include "anchorbench/engine/monte_carlo.hpp"
#include "monte_carlo_command.hpp"

namespace anchorbench::app {
namespace {

namespace fs = std::filesystem;
using studies::Fit;
using schema::InputError;
using report::PaperCell;

// The evaluation log, seeded with what --reuse and a killed run's running log already hold.
studies::EvaluationLog OpenLog(const CalibrateArgs& args, const schema::CalibrationSpec& spec,
                              const studies::CalibrationRuns& runs, const std::vector<PaperCell>& targets,
                              const std::vector<std::string>& row_names, const fs::path& running_log) {
  std::vector<std::string> keys, cell_names;
  for (const schema::FreeParameter& parameter : spec.parameters) keys.push_back(parameter.key);
  for (const PaperCell& cell : targets) cell_names.push_back(studies::CellName(cell, row_names));
  studies::EvaluationLog log(keys, cell_names, runs.Context());
  for (const fs::path& source : {fs::path(args.reuse), running_log}) {
    if (source.empty() || !fs::exists(source)) continue;
    int reused = 0;
    try {
      reused = log.Reuse(source);
    } catch (const InputError& e) {
      const std::string what = e.what();
      if (source != running_log || what.find(":1: ") == std::string::npos) throw;  // a line of it: cut that line
      throw InputError(what + "; it is the log of a killed calibration of other parameters: remove it to start afresh");
    }
    if (!args.quiet) std::cerr << "calibrate: " << reused << " evaluations known from " << source.string() << "\n";
  }
  log.AppendTo(running_log);
  return log;
}

// A calibrated config is a few lines per parameter; claimed before the first evaluation.
constexpr std::uintmax_t kCalibratedConfigBytes = 1 << 16;

// Every file the calibration reads (never replaced or removed): the calibration file, the
// experiment and its bases, the reused log.
std::vector<fs::path> Inputs(const CalibrateArgs& args, const schema::CalibrationSpec& spec) {
  std::vector<fs::path> inputs;
  for (const std::string& file : config::ConfigFiles(args.config)) inputs.emplace_back(file);
  for (const std::string& file : config::ConfigFiles(spec.experiment_path)) inputs.emplace_back(file);
  if (!args.reuse.empty()) inputs.emplace_back(args.reuse);
  return inputs;
}

// The reused log is read, never appended to or removed: it may not be this calibration's own
// running log (which is appended to, then removed at the end, and resumed from without --reuse).
void CheckReuse(const std::string& reuse, const fs::path& running_log) {
  if (reuse.empty()) return;
  std::error_code error;
  if (!fs::exists(reuse, error)) throw InputError("--reuse " + reuse + ": no such file");
  if (fs::is_directory(reuse, error)) throw InputError("--reuse " + reuse + ": is a folder, not an evaluation log");
  if (!fs::is_regular_file(reuse, error)) throw InputError("--reuse " + reuse + ": is not a regular file");
  if (fs::equivalent(reuse, running_log, error)) {
    throw InputError("--reuse " + reuse + ": is the running log of this --out, which a rerun without --reuse resumes "
                     "from; copy it elsewhere to reuse it");
  }
}

}  // namespace

int CalibrateCommand(const CalibrateArgs& args, const AppContext& app) {
  // Every input checked, and every output place claimed, before the first evaluation.
  const schema::CalibrationSpec spec = config::LoadCalibrationSpec(args.config);
  const std::string name = fs::path(args.config).stem().string();
  const MonteCarloSetup setup = SetUpMonteCarlo(args, name);
  const studies::CalibrationRuns runs(spec, app.components, app.executor, setup.threads);
  const schema::ExperimentConfig& experiment = runs.experiment();
  const std::vector<schema::RowConfig> rows = schema::RowsOf(experiment);
  const std::vector<PaperCell> targets = report::PaperTargets(rows);
  if (targets.empty()) {
    throw InputError(spec.experiment_path + ": no row carries the paper's values (`paper:`) and runs both " +
                     schema::kFixedWindowTrigger + " and " + schema::kPaperTrigger + ": nothing to calibrate to");
  }
  const fs::path running_log = setup.out.string() + ".evaluations.csv";  // beside the folder: resumable
  CheckReuse(args.reuse, running_log);
  const std::vector<fs::path> inputs = Inputs(args, spec);
  io::ResultFolder::Options options;
  options.overwrite = args.overwrite;
  options.expected_bytes = 1 << 22;
  options.inputs = inputs;
  io::ResultFolder out(setup.out, options);
  const fs::path experiment_path(spec.experiment_path);
  io::AtomicFile calibrated(experiment_path.parent_path() / (experiment_path.stem().string() + ".calibrated.yaml"),
                            args.overwrite, inputs, kCalibratedConfigBytes);
  std::vector<std::string> row_names;
  for (const schema::RowConfig& row : rows) row_names.push_back(row.name);
  std::error_code error;
  if (fs::exists(running_log, error) && !fs::is_regular_file(running_log, error)) {
    throw InputError(running_log.string() + ": is a folder (or not a regular file), not the evaluation log of a " +
                     "killed calibration; move it away");
  }
  studies::EvaluationLog log = OpenLog(args, spec, runs, targets, row_names, running_log);

  // The search, then the verification of its best point.
  Progress progress("calibrate " + name, args.quiet, "evaluations");
  Fit fit(spec, targets, runs.hand_values(), runs.FitEvaluator(), &log,
          [&](int done, int total) { progress.Update(done, total); });
  const studies::FitResult result = fit.Run();
  progress.Finish(static_cast<int>(log.evaluations().size()));
  std::vector<std::string> best;
  for (std::size_t p = 0; p < spec.parameters.size(); ++p) {
    best.push_back(spec.parameters[p].key + "=" + log.evaluations()[result.best].values[p]);
  }
  Progress verifying("verify " + name, args.quiet, "seeds");
  const studies::CalibrationOutcome outcome{spec,   row_names, experiment.realizations, fit,
                                              result, log,
                                           runs.Verify(best, [&](int done, int total) { verifying.Update(done, total); })};
  const double wall_time_s = progress.elapsed_s();  // the search and the verification
  verifying.Finish(static_cast<int>(spec.verify_seeds.size()));

  // The folder, then the calibrated config; the running log goes once both are in place.
  out.Write("evaluations.csv", [&](std::ostream& file) { studies::WriteEvaluationsCsv(file, log); });
  out.Write("verification.csv", [&](std::ostream& file) { studies::WriteVerificationCsv(file, outcome); });
  out.Write("profile.csv", [&](std::ostream& file) { studies::WriteProfileCsv(file, outcome); });
  std::ostringstream markdown;
  studies::WriteCalibrationMarkdown(markdown, outcome);
  out.Write("calibration.md", markdown.str());
  const schema::ExperimentConfig calibrated_experiment = runs.Experiment(best);
  std::vector<std::string> command_line{"calibrate " + args.config};
  if (!args.reuse.empty()) command_line.push_back("--reuse " + args.reuse);
  out.Write("manifest.json", report::ManifestJson(calibrated_experiment,
                                                   RunInfoOf(args, setup, app, calibrated_experiment, wall_time_s,
                                                             command_line)));
  calibrated.stream() << studies::CalibratedConfigYaml(outcome, experiment_path.filename().string());
  out.Commit();
  calibrated.Commit();
  fs::remove(running_log);
  if (!args.quiet) std::cout << markdown.str();
  return 0;
}

}  // namespace anchorbench::app
