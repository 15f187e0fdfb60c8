#pragma once

#include <cmath>
#include <string>

namespace anchorbench::estimator {

// A known anchor height (ours, docs/method.md "Flat paths"): the world z of the anchor, measured
// with a tape or taken from a building plan, with the standard deviation of that knowledge. It
// enters the double-difference LS and the NLS as one more residual (z_A - z_world_m) / sigma_m,
// so a flat path, which leaves the height to a mirror ambiguity, still initializes x-y from the
// ranges and z from the prior; where the ranges do observe the height, the two are weighed.
struct HeightPrior {
  double z_world_m = 0.0;
  double sigma_m = 0.1;

  bool IsValid(std::string* why) const {
    if (std::abs(z_world_m) <= 1e5 && sigma_m > 0.0 && sigma_m <= 1e4) return true;
    if (why) *why = "sigma_m must be in (0, 1e4] (and the prior's height within 1e5 m)";
    return false;
  }
  // The prior's squared residual in its own units: ((z - z_world_m) / sigma_m)^2.
  double Chi2(double z_m) const {
    const double r = (z_m - z_world_m) / sigma_m;
    return r * r;
  }
};

}  // namespace anchorbench::estimator
