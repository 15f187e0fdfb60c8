#pragma once

#include <string>
#include <vector>

#include "anchorbench/estimator/anchor_initializer.hpp"
#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/consistency_filter.hpp"
#include "anchorbench/estimator/ransac_solver.hpp"
#include "anchorbench/estimator/triggers.hpp"

namespace anchorbench::registry {

// The filter by name, with the settings of the built-in ones (the config's estimator.filter).
struct FilterConfig {
  std::string kind = "consistency";  // none | consistency | ransac | a filter of your own
  estimator::ConsistencyFilterOptions consistency;
  estimator::RansacOptions ransac;
};

// The estimator as an experiment describes it (the config's `estimator` section): its parts by
// registry name, and the typed options they are built with. Names are checked against the
// caller's registries (Components::Check); IsValid checks the typed options.
struct EstimatorConfig {
  std::string solver = "lm_adaptive";                                    // estimator.solver
  std::vector<std::string> triggers = {"fixed_window", "pdop_closest_point"};  // estimator.triggers, side by side
  FilterConfig filter;                                                   // estimator.filter
  estimator::TriggerOptions trigger;                                     // estimator.trigger
  estimator::InitializerOptions initializer;  // estimator.trigger.min_samples / retry_growth, estimator.buffer
  estimator::AnchorSolverOptions solver_options;                         // estimator.ls, estimator.nls

  bool IsValid(std::string* why) const;
};

}  // namespace anchorbench::registry
