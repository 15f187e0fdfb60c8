#pragma once

#include <memory>
#include <optional>

#include <Eigen/Core>

#include "anchorbench/estimator/init_trigger.hpp"
#include "anchorbench/estimator/ls_solver.hpp"
#include "anchorbench/estimator/registry.hpp"
#include "anchorbench/estimator/solver.hpp"

namespace anchorbench::estimator {

// What a trigger factory gets. The solver is the one the anchor is initialized with (before any
// batch filter wraps it), for triggers that look at its estimate; the truth is for the oracle.
struct TriggerContext {
  TriggerOptions options;
  LsOptions ls;
  std::shared_ptr<const Solver> solver;
  std::optional<Eigen::Vector3d> p_world_anchor_true;
};

using TriggerRegistry = Registry<InitTrigger, TriggerContext>;

// pdop_closest_point, pdop_ls, pdop_nls, pdop_true, fixed_window, sample_count, timeout.
void RegisterBuiltinTriggers(TriggerRegistry& registry);

}  // namespace anchorbench::estimator
