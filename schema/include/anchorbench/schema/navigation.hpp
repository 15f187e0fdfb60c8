#pragma once
// The navigation study's settings (the config's `navigation` section; docs/navigation.md): the
// odometry's drift and what the filter assumes. Plain data; nav::NavigationOptions is built from it.

#include <string>

namespace anchorbench::schema {

struct NavigationConfig {
  // The odometry's random walks and step noise (nav/odometry.hpp). The defaults are a wheel
  // odometry's order of magnitude (ours); configs/navigation_*.yaml set a VIO's where they model one.
  double sigma_bias_mps_per_sqrt_s = 0.004;
  double sigma_heading_rad_per_sqrt_s = 0.002;
  double sigma_step_m_per_sqrt_s = 0.02;
  double sigma_start_m = 0.05;  // the start position's error, per axis
  double sigma_range_m = 0.0;   // the range noise the filter assumes; 0: the row's ranging.sigma_range_m
  double gate_chi2 = 9.0;       // ranges beyond this (1 dof) are not used
  int fix_anchors = 3;          // a fix: at least this many anchors in use
  int kth_anchor = 3;           // the time to the k-th anchor is reported
  // An anchor the initializer refused as height_unobservable (its mirror fits as well): used
  // with its estimate as it is, or not at all.
  bool use_height_unobservable = false;

  bool IsValid(std::string* why) const;
};

}  // namespace anchorbench::schema
