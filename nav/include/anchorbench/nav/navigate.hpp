#pragma once
// One robot run with the navigation filter: the drifting odometry, and ranges to each anchor from
// the moment a trigger initialized it, with the estimate and covariance it reported (ours,
// docs/navigation.md). What it measures is what a user choosing a trigger wants downstream: the
// position error over the run and at its end, how long until anchors help, and how much of the
// run had a fix.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/nav/navigation_filter.hpp"
#include "anchorbench/nav/odometry.hpp"

namespace anchorbench::nav {

struct NavigationOptions {
  OdometryDrift drift;
  double sigma_start_m = 0.05;  // the start position's error, per axis
  double sigma_range_m = 0.1;   // the ranges' noise the filter assumes
  double gate_chi2 = 9.0;       // ranges beyond this (1 dof) are not used (outliers)
  int fix_anchors = 3;          // a fix: at least this many anchors in use
  int kth_anchor = 3;           // the time to the k-th anchor is reported
  double error_bin_s = 5.0;     // the error over time is kept as means over bins this long

  bool IsValid(std::string* why) const;
};

// An anchor as the filter may use it from t_init_s on.
struct UsableAnchor {
  int id = 0;
  double t_init_s = 0.0;
  Eigen::Vector3d p_world_anchor = Eigen::Vector3d::Zero();
  double bias_m = 0.0;
  Eigen::Matrix4d covariance = Eigen::Matrix4d::Zero();  // of (p_A, gamma)
  bool horizontal_only = false;  // its height mirror-ambiguous: x-y updates only (NavigationFilter)
};

struct RangeAt {
  std::size_t epoch = 0;  // index into the trajectory's times
  int anchor_id = 0;
  double range_m = 0.0;
};

struct NavigationOutcome {
  double rmse_m = 0.0;         // position error over every epoch
  double final_error_m = 0.0;  // at the last epoch
  std::optional<double> t_first_anchor_s, t_kth_anchor_s;  // since the run's start
  double fix_share = 0.0;      // the share of epochs with at least fix_anchors anchors in use
  long ranges_used = 0, ranges_gated = 0;
  // The position error over time: bin b is the mean over the epochs in [b, b + 1) error_bin_s
  // after the run's start (NaN: no epoch there, a gap in a recorded log).
  std::vector<double> error_by_bin_m;
};

// One method's run in one realization of an experiment's row (studies::RunNavigation).
struct NavigationRecord {
  int row = 0;
  int realization = 0;
  std::string method;  // a trigger, or a baseline
  NavigationOutcome outcome;
};

// `t_s` and `p_world_tag` are the true trajectory (one entry per epoch), `odometry` its steps
// (SimulateOdometry), `p_start` the filter's start (the truth plus the start error), `ranges` in
// epoch order. Throws std::invalid_argument on sizes that do not match.
NavigationOutcome Navigate(std::span<const double> t_s, std::span<const Eigen::Vector3d> p_world_tag,
                           std::span<const OdometryStep> odometry, const Eigen::Vector3d& p_start,
                           std::span<const RangeAt> ranges, std::vector<UsableAnchor> anchors,
                           const NavigationOptions& options);

}  // namespace anchorbench::nav
