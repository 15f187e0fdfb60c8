#pragma once

#include <optional>
#include <string>

#include <Eigen/Core>

#include "anchorbench/estimator/init_trigger.hpp"
#include "anchorbench/estimator/solve_result.hpp"

namespace anchorbench::schema {

// What is known of an anchor in simulation, or from a survey (anchors.csv).
struct AnchorTruth {
  Eigen::Vector3d p_world_anchor = Eigen::Vector3d::Zero();
  std::optional<double> bias_m;
};

// One attempt measured against the truth.
struct AttemptEvaluation {
  // On the attempt's data (the samples of its solve, or all buffered if none initialized it):
  double pdop_true = 0.0;                // Eqs. (2)-(3) at the true anchor (+inf if undefined)
  std::optional<double> bias_aware_hdop;  // its horizontal and vertical parts (TrueGeometry), finite only
  std::optional<double> bias_aware_vdop;
  std::optional<double> bias_aware_dop;  // finite only; sigma_d times it is the CRLB on the position error
  // Initialized attempts only:
  std::optional<Eigen::Vector3d> error_xyz_m;  // estimate - truth
  std::optional<double> error_m;               // its norm
  std::optional<double> bias_error_m;          // estimated - true bias, where the true bias is known
  // Normalized estimation error squared, e^T P^-1 e, of the solve's own covariance P: of the
  // position (3 dof), and of (p_A, gamma) where the true bias is known (4 dof). A credible
  // covariance gives a chi-square variable of that many degrees of freedom. Absent where P is
  // not positive definite (e.g. a solver that reports none).
  std::optional<double> nees_position;
  std::optional<double> nees;
  // The oracle's time (eval/oracle_latency.hpp), the same for every trigger of an anchor: its first
  // accepted sample, the earliest time after which the running fit stays within D (none: never
  // on all of the data), and this attempt's (t_init - t_first) / (t_oracle - t_first).
  std::optional<double> t_first_s;
  std::optional<double> t_oracle_s;
  std::optional<double> latency_ratio;
  // The ideal region's time (eval::IdealRegionTime; simulations only, whose noise is known) and
  // its (t_ideal - t_first) / (t_oracle - t_first): the latency the confidence itself costs.
  std::optional<double> t_ideal_s;
  std::optional<double> ideal_latency_ratio;
};

// One anchor with one trigger (a `method`) in one realization of one row: what happened, and how
// good it was where the truth is known. A row of attempts.csv (run) and of estimates.csv (replay).
struct Attempt {
  int row = 0;
  int realization = 0;
  int anchor_id = 0;
  std::string method;  // the trigger's name (fixed_window, pdop_closest_point, ...)
  bool initialized = false;
  std::optional<double> t_init_s;  // when the solve ran (online: the trigger; fixed: end of data)
  // Online, not initialized: when the latest failed solve (`solve`) ran. In memory only (the
  // navigation study uses a mirror-refused estimate from then on); not in the attempts' files.
  std::optional<double> t_failed_solve_s;
  int n_used = 0;                  // samples in the solve, or buffered so far if none ran
  double pdop_closest_point = 0.0;  // Eq. (4) at that moment, not at the estimate (+inf if undefined)
  std::optional<estimator::SolveResult> solve;  // absent if the solver never ran
  std::string status;                           // the solver's, or not_triggered / no_data
  std::optional<AttemptEvaluation> evaluation;  // where the truth is known
  // Not initialized: the test that held it back at the end (AnchorInitializer::why_not). Written
  // to the attempts' files as text; not read back.
  std::optional<estimator::Judgement> why_not;
  std::optional<double> crlb_m;  // sigma_d times the bias-aware DOP (simulations, where sigma_d is known)
  // Wall time of this trigger's pass over all of the realization's samples (filter, PDOP,
  // trigger, solves) divided by the number of anchors. Varies from run to run, so it goes to
  // timing files only, never into the deterministic tables.
  double compute_s = 0.0;
};

}  // namespace anchorbench::schema
