#pragma once

#include <optional>
#include <string>
#include <vector>

#include "anchorbench/estimator/anchor_initializer.hpp"
#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/certified_trigger.hpp"
#include "anchorbench/estimator/consistency_filter.hpp"
#include "anchorbench/estimator/height_prior.hpp"
#include "anchorbench/estimator/ransac_solver.hpp"
#include "anchorbench/estimator/triggers.hpp"

namespace anchorbench::schema {

// The filter by name, with the settings of the built-in ones (the config's estimator.filter).
struct FilterConfig {
  std::string kind = "consistency";  // none | consistency | ransac | a filter of your own
  estimator::ConsistencyFilterOptions consistency;
  estimator::RansacOptions ransac;
};

// Where an anchor's height prior comes from (the config's estimator.height_prior; ours,
// docs/method.md "Flat paths"). Every anchor gets z_m if it is set; with from_reference, each
// anchor gets its reference height instead (the truth in simulation, the survey in replay): the
// stand-in for a height measured per anchor, shifted by offset_m to measure what a wrong one costs.
struct HeightPriorConfig {
  bool enabled = false;
  double sigma_m = 0.1;
  double z_m = 0.0;
  bool from_reference = false;
  double offset_m = 0.0;

  bool IsValid(std::string* why) const;
  // The prior of one anchor; none when disabled. Throws std::invalid_argument when it comes from
  // a reference the anchor does not have.
  std::optional<estimator::HeightPrior> For(int anchor_id, const std::optional<Eigen::Vector3d>& p_world_reference) const;
};

// The estimator as an experiment describes it (the config's `estimator` section): its parts by
// registry name, and the typed options they are built with. Names are checked against the
// caller's registries (Components::Check); IsValid checks the typed options.
struct EstimatorConfig {
  std::string solver = "lm_adaptive";                                    // estimator.solver
  // estimator.triggers, side by side: the paper's two (Table I's columns) and ours, certified.
  std::vector<std::string> triggers = {"fixed_window", "pdop_closest_point", "certified"};
  FilterConfig filter;                                                   // estimator.filter
  estimator::TriggerOptions trigger;                                     // estimator.trigger
  estimator::InitializerOptions initializer;  // estimator.trigger.min_samples / retry_growth, estimator.buffer
  estimator::AnchorSolverOptions solver_options;                         // estimator.ls, estimator.nls
  HeightPriorConfig height_prior;                                        // estimator.height_prior
  estimator::CertificateOptions certificate;                             // estimator.certificate

  bool IsValid(std::string* why) const;
};

}  // namespace anchorbench::schema
