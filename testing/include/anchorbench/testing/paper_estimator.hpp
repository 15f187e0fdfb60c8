#pragma once

#include "anchorbench/schema/estimator_config.hpp"

namespace anchorbench::testing {

// The paper's estimator where the defaults are ours (configs/paper.yaml): its two triggers, no
// mirror check, the fixed cadence alone, the solvers' own covariances. Tests of the paper's
// behaviour start from it, so they do not move with the defaults for real logs.
inline schema::EstimatorConfig PaperEstimator() {
  schema::EstimatorConfig config;
  config.triggers = {"fixed_window", "pdop_closest_point"};
  config.initializer.height_check.enabled = false;
  config.trigger.evaluate_growth = 1.0;
  config.initializer.covariance.model_error_m = 0.0;
  config.initializer.covariance.travel_bias = false;
  config.initializer.covariance.correlated_noise = false;
  config.initializer.covariance.link_offset_m = 0.0;
  config.initializer.tag_biases.estimate = false;
  return config;
}

}  // namespace anchorbench::testing
