#pragma once

#include "anchorbench/schema/experiment.hpp"
#include "anchorbench/testing/paper_estimator.hpp"

namespace anchorbench::testing {

// A small two-row table: a short tunnel, a few anchors, a mix of trajectories.
inline schema::ExperimentConfig SmallTable() {
  schema::ExperimentConfig config;
  config.name = "small";
  config.seed = 7;
  config.realizations = 6;
  config.bootstrap_resamples = 200;
  config.estimator = PaperEstimator();
  config.scenario.tunnel.length_m = 60.0;
  config.scenario.tunnel.num_anchors = 4;
  config.scenario.trajectory.fraction_straight = 0.2;
  config.scenario.trajectory.fraction_planar = 0.2;
  config.scenario.ranging.outlier_probability = 0.05;
  config.scenario.ranging.sigma_position_m = 0.02;
  schema::RowConfig low{"low", config.scenario, config.estimator, std::nullopt};
  schema::RowConfig high = low;
  high.name = "high";
  high.scenario.ranging.sigma_range_m = 0.4;
  config.rows = {low, high};
  return config;
}

}  // namespace anchorbench::testing
