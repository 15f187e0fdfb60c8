#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "anchorbench/schema/experiment.hpp"

namespace anchorbench::schema {

// A simulation parameter `anchorbench calibrate` may move: a dotted key under `scenario` of the
// experiment, its bounds, and where its range comes from (what the paper says, or "not stated").
struct FreeParameter {
  std::string key;
  double min = 0.0, max = 0.0;
  std::string provenance;
};

// One NLopt stage: a derivative-free algorithm (GN_* or LN_*, deterministic) and its budget.
struct OptimizerStage {
  std::string algorithm;
  int max_evaluations = 0;
};

// A calibration (configs/calibrate_*.yaml; docs/calibration.md): the scenario parameters to fit so
// that an experiment's table matches the published values its rows carry (`paper:`).
struct CalibrationSpec {
  std::string path;             // the calibration file
  std::string experiment_path;  // the experiment it calibrates (relative paths resolved)
  std::vector<FreeParameter> parameters;
  // A weight per Table I column in the objective; 0 holds the column out of the fit (it is then
  // predicted, not fitted).
  PaperCells fit_weight{1.0, 1.0, 1.0, 0.0, 0.0};
  // Ours within +-band of the paper's value costs nothing; outside, the log-distance to the band's
  // edge counts. 0: the plain squared log-ratio.
  double band = 0.0;
  std::uint64_t seed = 1001;    // the fit's realizations: the same at every evaluation
  int realizations = 30;        // per row and evaluation
  std::vector<std::uint64_t> verify_seeds{2, 3, 4, 5, 6};  // at the experiment's full size
  OptimizerStage global{"GN_DIRECT_L", 150};
  OptimizerStage local{"LN_SBPLX", 60};
  double profile_step = 0.1;    // profiles at +-1 and +-2.5 steps of each parameter's range
};

}  // namespace anchorbench::schema
