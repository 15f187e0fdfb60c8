#include <filesystem>
#include <iostream>
#include <sstream>

#include "anchorbench/calibrate/calibration_report.hpp"
#include "anchorbench/calibrate/evaluation_log.hpp"
#include "anchorbench/calibrate/fit.hpp"
#include "anchorbench/config/load_calibration.hpp"
#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/atomic_file.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/io/input_error.hpp"
#include "anchorbench/report/paper_cells.hpp"
#include "anchorbench/report/summary.hpp"
#include "anchorbench/runner/monte_carlo.hpp"
#include "monte_carlo_command.hpp"

namespace anchorbench::app {
namespace {

namespace fs = std::filesystem;
using calibrate::Fit;
using io::InputError;
using report::PaperCell;

// The experiment with these overrides, run and compared with the paper's cells.
std::vector<PaperCell> RunCells(const runner::CalibrationSpec& spec, std::vector<std::string> overrides,
                                std::uint64_t seed, std::optional<int> realizations, bool intervals, int threads,
                                const AppContext& app) {
  overrides.push_back("seed=" + std::to_string(seed));
  if (realizations) overrides.push_back("realizations=" + std::to_string(*realizations));
  if (!intervals) overrides.push_back("bootstrap_resamples=0");  // the fit needs no intervals
  const runner::ExperimentConfig config = config::LoadConfig(spec.experiment_path, overrides, app.parts);
  const std::vector<runner::RowConfig> rows = runner::RowsOf(config);
  const std::vector<runner::Attempt> attempts = runner::RunMonteCarlo(config, app.parts, {threads, nullptr});
  return report::CompareWithPaper(
      report::Summarize(attempts, rows, config.realizations, config.bootstrap_resamples, config.seed), rows);
}

// The experiment's own value of each parameter, inside its bounds; and the experiment valid at
// each bound, so no evaluation of the search can fail on input.
std::vector<double> CheckParameters(const runner::CalibrationSpec& spec, const runner::ExperimentConfig& experiment,
                                    const AppContext& app) {
  const std::string resolved = config::ToYaml(experiment);
  std::vector<double> hand;
  for (std::size_t p = 0; p < spec.parameters.size(); ++p) {
    const runner::FreeParameter& parameter = spec.parameters[p];
    const std::string what = spec.path + ": parameters[" + std::to_string(p) + "]";
    hand.push_back(config::NumberAt(resolved, parameter.key, what));
    if (hand.back() < parameter.min || hand.back() > parameter.max) {
      throw InputError(what + " (" + parameter.key + "): the experiment's value " + io::FormatNumber(hand.back()) +
                       " lies outside [min, max]; widen the bounds");
    }
    for (double u : {0.0, 1.0}) {
      const std::string assignment = parameter.key + "=" + Fit::ValueText(parameter, u);
      try {
        const runner::ExperimentConfig at_bound = config::LoadConfig(spec.experiment_path, {assignment}, app.parts);
        runner::CheckWork(at_bound);
        runner::CheckRows(runner::RowsOf(at_bound), app.parts);
      } catch (const InputError& e) {
        throw InputError(what + " (" + parameter.key + ") at its " + (u == 0.0 ? "min" : "max") + ": " + e.what());
      }
    }
  }
  return hand;
}

// What decides an evaluation's cells besides the parameters: lines of a log made with anything
// else are not reused.
std::uint64_t Context(const runner::CalibrationSpec& spec, const runner::ExperimentConfig& experiment) {
  return calibrate::Fnv1a64(config::ToYaml(experiment) + "\nfit seed " + std::to_string(spec.seed) +
                            "\nfit realizations " + std::to_string(spec.realizations));
}

}  // namespace

int CalibrateCommand(const CalibrateArgs& args, const AppContext& app) {
  // Every input checked before the first evaluation.
  const runner::CalibrationSpec spec = config::LoadCalibrationSpec(args.config);
  const runner::ExperimentConfig experiment = config::LoadConfig(spec.experiment_path, {}, app.parts);
  const std::vector<runner::RowConfig> rows = runner::RowsOf(experiment);
  const std::vector<PaperCell> targets = report::PaperTargets(rows);
  if (targets.empty()) {
    throw InputError(spec.experiment_path + ": no row carries the paper's values (`paper:`) and runs both " +
                     runner::kFixedWindowTrigger + " and " + runner::kPaperTrigger + ": nothing to calibrate to");
  }
  const std::vector<double> hand = CheckParameters(spec, experiment, app);
  if (!args.reuse.empty() && !fs::is_regular_file(args.reuse)) throw InputError(args.reuse + ": no such file (--reuse)");

  const std::string name = fs::path(args.config).stem().string();
  const MonteCarloSetup setup = SetUpMonteCarlo(args, name);
  const std::unique_ptr<io::ResultFolder> out = OpenResultFolder(args, setup, 1 << 22);
  const fs::path experiment_path(spec.experiment_path);
  io::AtomicFile calibrated(experiment_path.parent_path() / (experiment_path.stem().string() + ".calibrated.yaml"),
                            args.overwrite, {args.config, spec.experiment_path});

  std::vector<std::string> row_names, keys, cell_names;
  for (const runner::RowConfig& row : rows) row_names.push_back(row.name);
  for (const runner::FreeParameter& parameter : spec.parameters) keys.push_back(parameter.key);
  for (const PaperCell& cell : targets) cell_names.push_back(calibrate::CellName(cell, row_names));
  calibrate::EvaluationLog log(keys, cell_names, Context(spec, experiment));
  // The running log beside the folder: a killed calibration resumes from it.
  const fs::path running_log = setup.out.string() + ".evaluations.csv";
  for (const fs::path& source : {fs::path(args.reuse), running_log}) {
    if (source.empty() || !fs::exists(source)) continue;
    const int reused = log.Reuse(source);
    if (!args.quiet) std::cerr << "calibrate: " << reused << " evaluations known from " << source.string() << "\n";
  }
  log.AppendTo(running_log);

  // Init and >1m are counts over all attempts: the fit's, at fewer realizations, are scaled up to
  // the experiment's size before they are compared with the paper's.
  const double count_scale = static_cast<double>(experiment.realizations) / spec.realizations;
  Progress progress("calibrate " + name, args.quiet);
  Fit fit(
      spec, targets, hand,
      [&](const std::vector<std::string>& overrides) {
        std::vector<std::optional<double>> ours;
        for (const PaperCell& cell : RunCells(spec, overrides, spec.seed, spec.realizations, false, setup.threads, app)) {
          ours.push_back(cell.ours);
          if (ours.back() && (cell.column == report::PaperColumn::kInit || cell.column == report::PaperColumn::kGt1m)) {
            *ours.back() *= count_scale;  // counts at the table's size
          }
        }
        return ours;
      },
      &log, [&](int done, int total) { progress.Update(done, total); });
  const calibrate::FitResult result = fit.Run();
  progress.Finish(static_cast<int>(log.evaluations().size()));

  // Verification: the experiment as configured and as calibrated, full size, unseen seeds.
  std::vector<std::string> best;
  for (std::size_t p = 0; p < spec.parameters.size(); ++p) {
    best.push_back(spec.parameters[p].key + "=" + log.evaluations()[result.best].values[p]);
  }
  calibrate::CalibrationOutcome outcome{spec, row_names, experiment.realizations, fit, result, log, {}};
  Progress verifying("verify " + name, args.quiet);
  for (std::uint64_t seed : spec.verify_seeds) {
    outcome.verification.push_back({seed, RunCells(spec, {}, seed, std::nullopt, true, setup.threads, app),
                                    RunCells(spec, best, seed, std::nullopt, true, setup.threads, app)});
    verifying.Update(static_cast<int>(outcome.verification.size()), static_cast<int>(spec.verify_seeds.size()));
  }
  const double wall_time_s = progress.elapsed_s() + verifying.elapsed_s();
  verifying.Finish(static_cast<int>(spec.verify_seeds.size()));

  out->Write("evaluations.csv", [&](std::ostream& file) { calibrate::WriteEvaluationsCsv(file, log); });
  out->Write("verification.csv", [&](std::ostream& file) { calibrate::WriteVerificationCsv(file, outcome); });
  out->Write("profile.csv", [&](std::ostream& file) { calibrate::WriteProfileCsv(file, outcome); });
  std::ostringstream markdown;
  calibrate::WriteCalibrationMarkdown(markdown, outcome);
  out->Write("calibration.md", markdown.str());
  const runner::ExperimentConfig calibrated_experiment = config::LoadConfig(spec.experiment_path, best, app.parts);
  std::vector<std::string> command_line{"calibrate " + args.config};
  if (!args.reuse.empty()) command_line.push_back("--reuse " + args.reuse);
  out->Write("manifest.json", report::ManifestJson(calibrated_experiment,
                                                   RunInfoOf(args, setup, app, calibrated_experiment, wall_time_s,
                                                             command_line)));
  calibrated.stream() << calibrate::CalibratedConfigYaml(outcome, experiment_path.filename().string());
  out->Commit();
  calibrated.Commit();
  fs::remove(running_log);
  if (!args.quiet) std::cout << markdown.str();
  return 0;
}

}  // namespace anchorbench::app
