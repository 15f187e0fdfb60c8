#pragma once
// What `anchorbench calibrate` writes (results/<name>/; docs/calibration.md): the search, its
// verification on unseen seeds at full size, and the calibrated experiment.

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "anchorbench/studies/evaluation_log.hpp"
#include "anchorbench/studies/fit.hpp"
#include "anchorbench/report/paper_cells.hpp"
#include "anchorbench/schema/calibration_spec.hpp"

namespace anchorbench::studies {

// The experiment as configured (before) and as calibrated (after) on one unseen seed, at the
// experiment's own size, with its 95% intervals.
struct Verification {
  std::uint64_t seed = 0;
  std::vector<report::PaperCell> before, after;
};

struct CalibrationOutcome {
  const schema::CalibrationSpec& spec;
  std::vector<std::string> row_names;  // by row index
  int full_realizations = 0;           // the experiment's (verification) size
  const Fit& fit;
  const FitResult& result;
  const EvaluationLog& log;
  std::vector<Verification> verification;
};

// "1.fixed.avg_m": a cell's column name in evaluations.csv.
std::string CellName(const report::PaperCell& cell, const std::vector<std::string>& row_names);

// calibration.md: parameters, objective, verification, held-out prediction, profiles, reachability.
void WriteCalibrationMarkdown(std::ostream& out, const CalibrationOutcome& outcome);
// evaluations.csv: every evaluation of this run, in order (EvaluationLog's columns).
void WriteEvaluationsCsv(std::ostream& out, const EvaluationLog& log);
// verification.csv: seed,config,row,method,column,paper,ours,lo,hi,scored,fitted,within_25pct,paper_inside
void WriteVerificationCsv(std::ostream& out, const CalibrationOutcome& outcome);
// profile.csv: key,steps,value,objective,rise
void WriteProfileCsv(std::ostream& out, const CalibrationOutcome& outcome);

// The calibrated experiment: `base:` the experiment file (its name, relative to the same folder)
// with the fitted values, each commented with its bounds and provenance.
std::string CalibratedConfigYaml(const CalibrationOutcome& outcome, const std::string& experiment_file_name);

}  // namespace anchorbench::studies
