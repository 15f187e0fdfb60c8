#pragma once
// The navigation study's settings (the config's `navigation` section; docs/navigation.md): the
// odometry's drift and what the filter assumes. Plain data; nav::NavigationOptions is built from it.

#include <string>

#include "anchorbench/estimator/enum_names.hpp"

namespace anchorbench::schema {

// What the filter does with an anchor the initializer refused as height_unobservable (its
// mirror through the flat path's plane fits as well).
enum class MirroredAnchorUse {
  kSkip,        // not used
  kHorizontal,  // used for x-y only (nav::NavigationFilter::AddAnchor's horizontal_only)
  kAsIs,        // used with its estimate as it is, height included
};
inline constexpr estimator::EnumNames<MirroredAnchorUse, 3> kMirroredAnchorUseNames({
    {MirroredAnchorUse::kSkip, "skip"}, {MirroredAnchorUse::kHorizontal, "xy_only"}, {MirroredAnchorUse::kAsIs, "as_is"}});

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
  double error_bin_s = 5.0;     // navigation_error.csv's time bins
  MirroredAnchorUse height_unobservable = MirroredAnchorUse::kSkip;

  bool IsValid(std::string* why) const;
};

}  // namespace anchorbench::schema
