#include <filesystem>
#include <iostream>
#include <sstream>

#include "anchorbench/engine/calibration_report.hpp"
#include "anchorbench/engine/evaluation_log.hpp"
#include "anchorbench/engine/fit.hpp"
#include "anchorbench/config/config_yaml.hpp"
#include "anchorbench/config/load_calibration.hpp"
#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/atomic_file.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/io/hash.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/report/paper_cells.hpp"
#include "anchorbench/report/summary.hpp"
#include "anchorbench/engine/monte_carlo.hpp"
#include "anchorbench/engine/run_plan.hpp"
#include "monte_carlo_command.hpp"

namespace anchorbench::app {
namespace {

namespace fs = std::filesystem;
using engine::Fit;
using schema::InputError;
using report::PaperCell;

// The experiment with these overrides, run and compared with the paper's cells.
std::vector<PaperCell> RunCells(const schema::CalibrationSpec& spec, std::vector<std::string> overrides,
                                std::uint64_t seed, std::optional<int> realizations, bool intervals, int threads,
                                const AppContext& app) {
  overrides.push_back("seed=" + std::to_string(seed));
  if (realizations) overrides.push_back("realizations=" + std::to_string(*realizations));
  if (!intervals) overrides.push_back("bootstrap_resamples=0");  // the fit needs no intervals
  // The paper's cells are of its two triggers: the others an experiment runs beside them (ours:
  // certified in Table I) would cost without changing a cell.
  overrides.push_back(std::string("estimator.triggers=[") + schema::kFixedWindowTrigger + "," + schema::kPaperTrigger + "]");
  const schema::ExperimentConfig config = config::LoadConfig(spec.experiment_path, overrides, app.components);
  const std::vector<schema::RowConfig> rows = schema::RowsOf(config);
  engine::CheckExperiment(config, app.components);
  const engine::Plan plan({config});
  const std::vector<schema::Attempt> attempts = engine::RunWholePlan(plan, app.executor, threads).front().attempts;
  return report::CompareWithPaper(
      report::Summarize(attempts, rows, config.realizations, config.bootstrap_resamples, config.seed), rows);
}

// The experiment's own value of each parameter, inside its bounds; and the experiment valid at
// each bound, so no evaluation of the search can fail on input.
std::vector<double> CheckParameters(const schema::CalibrationSpec& spec, const schema::ExperimentConfig& experiment,
                                    const AppContext& app) {
  const std::string resolved = config::ToYaml(experiment);
  std::vector<double> hand;
  for (std::size_t p = 0; p < spec.parameters.size(); ++p) {
    const schema::FreeParameter& parameter = spec.parameters[p];
    const std::string what = spec.path + ": parameters[" + std::to_string(p) + "]";
    hand.push_back(config::NumberAt(resolved, parameter.key, what));
    if (hand.back() < parameter.min || hand.back() > parameter.max) {
      throw InputError(what + " (" + parameter.key + "): the experiment's value " + io::FormatNumber(hand.back()) +
                       " lies outside [min, max]; widen the bounds");
    }
    for (double u : {0.0, 1.0}) {
      const std::string assignment = parameter.key + "=" + Fit::ValueText(parameter, u);
      try {
        const schema::ExperimentConfig at_bound = config::LoadConfig(spec.experiment_path, {assignment}, app.components);
        engine::CheckExperiment(at_bound, app.components);
      } catch (const InputError& e) {
        throw InputError(what + " (" + parameter.key + ") at its " + (u == 0.0 ? "min" : "max") + ": " + e.what());
      }
    }
  }
  return hand;
}

// What decides an evaluation's cells besides the parameters: lines of a log made with anything
// else are not reused.
std::uint64_t Context(const schema::CalibrationSpec& spec, const schema::ExperimentConfig& experiment) {
  return io::Fnv1a64(config::ToYaml(experiment) + "\nfit seed " + std::to_string(spec.seed) +
                            "\nfit realizations " + std::to_string(spec.realizations));
}

// The evaluation log, seeded with what --reuse and a killed run's running log already hold.
engine::EvaluationLog OpenLog(const CalibrateArgs& args, const schema::CalibrationSpec& spec,
                                 const schema::ExperimentConfig& experiment, const std::vector<PaperCell>& targets,
                                 const std::vector<std::string>& row_names, const fs::path& running_log) {
  std::vector<std::string> keys, cell_names;
  for (const schema::FreeParameter& parameter : spec.parameters) keys.push_back(parameter.key);
  for (const PaperCell& cell : targets) cell_names.push_back(engine::CellName(cell, row_names));
  engine::EvaluationLog log(keys, cell_names, Context(spec, experiment));
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

// Our cells at the fit's seed and size, with Init and >1m (counts over all attempts) scaled up to
// the experiment's size before they meet the paper's.
engine::CellEvaluator FitEvaluator(const schema::CalibrationSpec& spec, int full_realizations, int threads,
                                      const AppContext& app) {
  const double count_scale = static_cast<double>(full_realizations) / spec.realizations;
  return [&spec, count_scale, threads, &app](const std::vector<std::string>& overrides) {
    std::vector<std::optional<double>> ours;
    for (const PaperCell& cell : RunCells(spec, overrides, spec.seed, spec.realizations, false, threads, app)) {
      ours.push_back(cell.ours);
      if (ours.back() && (cell.column == report::PaperColumn::kInit || cell.column == report::PaperColumn::kGt1m)) {
        *ours.back() *= count_scale;
      }
    }
    return ours;
  };
}

// The experiment as configured and as calibrated (`best`), full size, on the unseen seeds.
std::vector<engine::Verification> Verify(const schema::CalibrationSpec& spec, const std::vector<std::string>& best,
                                            int threads, Progress& progress, const AppContext& app) {
  std::vector<engine::Verification> verification;
  for (std::uint64_t seed : spec.verify_seeds) {
    verification.push_back({seed, RunCells(spec, {}, seed, std::nullopt, true, threads, app),
                            RunCells(spec, best, seed, std::nullopt, true, threads, app)});
    progress.Update(static_cast<int>(verification.size()), static_cast<int>(spec.verify_seeds.size()));
  }
  return verification;
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

void CheckReuse(const std::string& reuse) {
  if (reuse.empty()) return;
  std::error_code error;
  if (!fs::exists(reuse, error)) throw InputError("--reuse " + reuse + ": no such file");
  if (fs::is_directory(reuse, error)) throw InputError("--reuse " + reuse + ": is a folder, not an evaluation log");
  if (!fs::is_regular_file(reuse, error)) throw InputError("--reuse " + reuse + ": is not a regular file");
}

}  // namespace

int CalibrateCommand(const CalibrateArgs& args, const AppContext& app) {
  // Every input checked, and every output place claimed, before the first evaluation.
  const schema::CalibrationSpec spec = config::LoadCalibrationSpec(args.config);
  const schema::ExperimentConfig experiment = config::LoadConfig(spec.experiment_path, {}, app.components);
  const std::vector<schema::RowConfig> rows = schema::RowsOf(experiment);
  const std::vector<PaperCell> targets = report::PaperTargets(rows);
  if (targets.empty()) {
    throw InputError(spec.experiment_path + ": no row carries the paper's values (`paper:`) and runs both " +
                     schema::kFixedWindowTrigger + " and " + schema::kPaperTrigger + ": nothing to calibrate to");
  }
  const std::vector<double> hand = CheckParameters(spec, experiment, app);
  CheckReuse(args.reuse);
  const std::string name = fs::path(args.config).stem().string();
  const MonteCarloSetup setup = SetUpMonteCarlo(args, name);
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
  const fs::path running_log = setup.out.string() + ".evaluations.csv";  // beside the folder: resumable
  std::error_code error;
  if (fs::exists(running_log, error) && !fs::is_regular_file(running_log, error)) {
    throw InputError(running_log.string() + ": is a folder (or not a regular file), not the evaluation log of a " +
                     "killed calibration; move it away");
  }
  engine::EvaluationLog log = OpenLog(args, spec, experiment, targets, row_names, running_log);

  // The search, then the verification of its best point.
  Progress progress("calibrate " + name, args.quiet, "evaluations");
  Fit fit(spec, targets, hand, FitEvaluator(spec, experiment.realizations, setup.threads, app), &log,
          [&](int done, int total) { progress.Update(done, total); });
  const engine::FitResult result = fit.Run();
  progress.Finish(static_cast<int>(log.evaluations().size()));
  std::vector<std::string> best;
  for (std::size_t p = 0; p < spec.parameters.size(); ++p) {
    best.push_back(spec.parameters[p].key + "=" + log.evaluations()[result.best].values[p]);
  }
  Progress verifying("verify " + name, args.quiet, "seeds");
  const engine::CalibrationOutcome outcome{spec,   row_names, experiment.realizations, fit,
                                              result, log,       Verify(spec, best, setup.threads, verifying, app)};
  const double wall_time_s = progress.elapsed_s();  // the search and the verification
  verifying.Finish(static_cast<int>(spec.verify_seeds.size()));

  // The folder, then the calibrated config; the running log goes once both are in place.
  out.Write("evaluations.csv", [&](std::ostream& file) { engine::WriteEvaluationsCsv(file, log); });
  out.Write("verification.csv", [&](std::ostream& file) { engine::WriteVerificationCsv(file, outcome); });
  out.Write("profile.csv", [&](std::ostream& file) { engine::WriteProfileCsv(file, outcome); });
  std::ostringstream markdown;
  engine::WriteCalibrationMarkdown(markdown, outcome);
  out.Write("calibration.md", markdown.str());
  const schema::ExperimentConfig calibrated_experiment = config::LoadConfig(spec.experiment_path, best, app.components);
  std::vector<std::string> command_line{"calibrate " + args.config};
  if (!args.reuse.empty()) command_line.push_back("--reuse " + args.reuse);
  out.Write("manifest.json", report::ManifestJson(calibrated_experiment,
                                                   RunInfoOf(args, setup, app, calibrated_experiment, wall_time_s,
                                                             command_line)));
  calibrated.stream() << engine::CalibratedConfigYaml(outcome, experiment_path.filename().string());
  out.Commit();
  calibrated.Commit();
  fs::remove(running_log);
  if (!args.quiet) std::cout << markdown.str();
  return 0;
}

}  // namespace anchorbench::app
