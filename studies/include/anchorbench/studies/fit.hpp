#pragma once
// The search of `anchorbench calibrate`: the experiment as configured, a global NLopt stage over
// the parameters' box, a local stage from the better of the two, then a profile of each parameter
// around the best point. Every evaluation runs the experiment at the fit's seed (the same
// realizations each time: common random numbers), so the objective is a deterministic function
// of the parameters and the search repeats exactly.

#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "anchorbench/studies/evaluation_log.hpp"
#include "anchorbench/report/paper_cells.hpp"
#include "anchorbench/schema/calibration_spec.hpp"

namespace anchorbench::studies {

// Our value of each target cell with the experiment's parameters set by `overrides`
// ("key=value", one per parameter), at the fit's seed and realizations.
using CellEvaluator = std::function<std::vector<std::optional<double>>(const std::vector<std::string>& overrides)>;

// A profile point: the best point with one parameter moved by `steps` x profile_step of its range.
struct ProfilePoint {
  std::size_t parameter = 0;
  double steps = 0.0;
  std::size_t evaluation = 0;  // index into the log's evaluations
};

struct FitResult {
  std::size_t hand = 0;  // the experiment as configured
  std::size_t best = 0;  // the lowest objective (the earliest of equals)
  std::vector<ProfilePoint> profile;
};

class Fit {
 public:
  // `hand_values`: the experiment's own values of the parameters (inside their bounds).
  Fit(const schema::CalibrationSpec& spec, std::vector<report::PaperCell> targets, std::vector<double> hand_values,
      CellEvaluator evaluate, EvaluationLog* log, std::function<void(int done, int total)> progress = {});

  FitResult Run();

  // The target cells with ours from an evaluation.
  std::vector<report::PaperCell> CellsOf(const Evaluation& evaluation) const;
  // The text a parameter value is evaluated at: 6 significant digits of min + u (max - min), u on
  // a grid of 1e-4 (the calibrated config prints exactly what was evaluated).
  static std::string ValueText(const schema::FreeParameter& parameter, double u);

 private:
  double Evaluate(const std::vector<double>& u, const std::string& stage);
  double EvaluateTexts(const std::vector<std::string>& texts, const std::vector<double>& u, const std::string& stage);
  void RunStage(const schema::OptimizerStage& stage, const std::string& name, std::vector<double>* u);
  std::size_t Best() const;
  int Total() const;

  const schema::CalibrationSpec& spec_;
  std::vector<report::PaperCell> targets_;
  std::vector<double> hand_values_;
  CellEvaluator evaluate_;
  EvaluationLog* log_;
  std::function<void(int, int)> progress_;
  std::vector<std::vector<double>> u_;  // per evaluation, the point in the unit box
  std::exception_ptr error_;            // an evaluation's error, rethrown once NLopt has stopped
};

}  // namespace anchorbench::studies
