#include "anchorbench/studies/calibration_runs.hpp"

#include "anchorbench/config/load_calibration.hpp"
#include "anchorbench/config/load_config.hpp"
#include "anchorbench/engine/monte_carlo.hpp"
#include "anchorbench/engine/run_plan.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/io/hash.hpp"
#include "anchorbench/report/summary.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::studies {

using engine::CheckExperiment;
using engine::Executor;
using engine::Plan;
using engine::RunWholePlan;

using report::PaperCell;
using schema::InputError;

CalibrationRuns::CalibrationRuns(const schema::CalibrationSpec& spec, const registry::Components& components,
                                 Executor& executor, int threads)
    : spec_(spec),
      components_(components),
      executor_(executor),
      threads_(threads),
      document_(config::ReadConfigDocument(spec.experiment_path)),
      experiment_(config::LoadConfig(document_, {}, components)),
      hand_values_(CheckParameters()) {}

std::vector<double> CalibrationRuns::CheckParameters() const {
  const std::string resolved = config::ToYaml(experiment_);
  std::vector<double> hand;
  for (std::size_t p = 0; p < spec_.parameters.size(); ++p) {
    const schema::FreeParameter& parameter = spec_.parameters[p];
    const std::string what = spec_.path + ": parameters[" + std::to_string(p) + "]";
    hand.push_back(config::NumberAt(resolved, parameter.key, what));
    if (hand.back() < parameter.min || hand.back() > parameter.max) {
      throw InputError(what + " (" + parameter.key + "): the experiment's value " + io::FormatNumber(hand.back()) +
                       " lies outside [min, max]; widen the bounds");
    }
    for (double u : {0.0, 1.0}) {
      try {
        CheckExperiment(Experiment({parameter.key + "=" + Fit::ValueText(parameter, u)}), components_);
      } catch (const InputError& e) {
        throw InputError(what + " (" + parameter.key + ") at its " + (u == 0.0 ? "min" : "max") + ": " + e.what());
      }
    }
  }
  return hand;
}

std::uint64_t CalibrationRuns::Context() const {
  return io::Fnv1a64(config::ToYaml(experiment_) + "\nfit seed " + std::to_string(spec_.seed) +
                     "\nfit realizations " + std::to_string(spec_.realizations));
}

schema::ExperimentConfig CalibrationRuns::Experiment(const std::vector<std::string>& assignments) const {
  return config::LoadConfig(document_, assignments, components_);
}

std::vector<PaperCell> CalibrationRuns::Cells(std::vector<std::string> assignments, std::uint64_t seed,
                                              std::optional<int> realizations, bool intervals) const {
  assignments.push_back("seed=" + std::to_string(seed));
  if (realizations) assignments.push_back("realizations=" + std::to_string(*realizations));
  if (!intervals) assignments.push_back("bootstrap_resamples=0");  // the fit needs no intervals
  // The paper's cells are of its two triggers: the others an experiment runs beside them (ours:
  // certified in Table I) would cost without changing a cell.
  assignments.push_back(std::string("estimator.triggers=[") + schema::kFixedWindowTrigger + "," +
                        schema::kPaperTrigger + "]");
  assignments.push_back("estimator.oracle_latency=false");  // nor does the oracle's pass
  const schema::ExperimentConfig config = Experiment(assignments);
  CheckExperiment(config, components_);
  const std::vector<schema::RowConfig> rows = schema::RowsOf(config);
  const Plan plan({config});
  const std::vector<schema::Attempt> attempts = RunWholePlan(plan, executor_, threads_).front().attempts;
  return report::CompareWithPaper(
      report::Summarize(attempts, rows, config.realizations, config.bootstrap_resamples, config.seed), rows);
}

CellEvaluator CalibrationRuns::FitEvaluator() const {
  const double count_scale = static_cast<double>(experiment_.realizations) / spec_.realizations;
  return [this, count_scale](const std::vector<std::string>& assignments) {
    std::vector<std::optional<double>> ours;
    for (const PaperCell& cell : Cells(assignments, spec_.seed, spec_.realizations, false)) {
      ours.push_back(cell.ours);
      if (ours.back() && (cell.column == report::PaperColumn::kInit || cell.column == report::PaperColumn::kGt1m)) {
        *ours.back() *= count_scale;
      }
    }
    return ours;
  };
}

std::vector<Verification> CalibrationRuns::Verify(const std::vector<std::string>& best,
                                                  const std::function<void(int, int)>& progress) const {
  std::vector<Verification> verification;
  for (std::uint64_t seed : spec_.verify_seeds) {
    verification.push_back({seed, Cells({}, seed, std::nullopt, true), Cells(best, seed, std::nullopt, true)});
    if (progress) progress(static_cast<int>(verification.size()), static_cast<int>(spec_.verify_seeds.size()));
  }
  return verification;
}

}  // namespace anchorbench::studies
