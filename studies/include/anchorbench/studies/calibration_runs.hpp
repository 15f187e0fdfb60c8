#pragma once
// The experiment runs of `anchorbench calibrate`: the experiment with a parameter assignment, at
// a seed and size, compared with the paper's cells. The experiment's file (and its bases) is read
// once, when the runs are made; every evaluation lays its assignment over that document.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "anchorbench/config/config_yaml.hpp"
#include "anchorbench/studies/calibration_report.hpp"
#include "anchorbench/engine/executor.hpp"
#include "anchorbench/studies/fit.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/report/paper_cells.hpp"
#include "anchorbench/schema/calibration_spec.hpp"
#include "anchorbench/schema/experiment.hpp"

namespace anchorbench::studies {

class CalibrationRuns {
 public:
  // Reads spec.experiment_path; throws InputError for a bad experiment or a parameter whose
  // experiment value lies outside its bounds or whose bounds make the experiment invalid, so that
  // no evaluation of the search can fail on input.
  CalibrationRuns(const schema::CalibrationSpec& spec, const registry::Components& components, engine::Executor& executor,
                  int threads);

  const schema::ExperimentConfig& experiment() const { return experiment_; }
  // The experiment's own value of each parameter (inside its bounds).
  const std::vector<double>& hand_values() const { return hand_values_; }
  // What decides an evaluation's cells besides the parameters (the evaluation log's context):
  // lines of a log made with anything else are not reused.
  std::uint64_t Context() const;

  // The experiment with `assignments` ("key=value") at `seed`, `realizations` (none: the
  // experiment's) and with or without intervals, compared with the paper's cells.
  std::vector<report::PaperCell> Cells(std::vector<std::string> assignments, std::uint64_t seed,
                                       std::optional<int> realizations, bool intervals) const;
  // The experiment under `assignments`, as a calibrated config would make it.
  schema::ExperimentConfig Experiment(const std::vector<std::string>& assignments) const;

  // The fit's evaluator: our cells at the fit's seed and size, with Init and >1m (counts over all
  // attempts) scaled up to the experiment's size before they meet the paper's.
  CellEvaluator FitEvaluator() const;
  // The experiment as configured and as calibrated (`best`), full size, on the unseen seeds;
  // `progress(done, total)` after each seed.
  std::vector<Verification> Verify(const std::vector<std::string>& best,
                                   const std::function<void(int, int)>& progress = {}) const;

 private:
  std::vector<double> CheckParameters() const;

  const schema::CalibrationSpec& spec_;
  const registry::Components& components_;
  engine::Executor& executor_;
  int threads_;
  config::ConfigDocument document_;
  schema::ExperimentConfig experiment_;
  std::vector<double> hand_values_;
};

}  // namespace anchorbench::studies
