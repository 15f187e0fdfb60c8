#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "anchorbench/estimator/anchor_initializer.hpp"
#include "anchorbench/estimator/filter_registry.hpp"
#include "anchorbench/estimator/solver_registry.hpp"
#include "anchorbench/estimator/trigger_registry.hpp"

namespace anchorbench::estimator {

// The three registries of named parts an initializer is built from. Owned by the caller.
struct Components {
  SolverRegistry solvers{"solver"};
  FilterRegistry filters{"filter"};
  TriggerRegistry triggers{"trigger"};
};

// Fills all three with the built-ins (RegisterBuiltinSolvers, ...Filters, ...Triggers).
void RegisterBuiltins(Components& components);
// A Components holding just the built-ins.
Components MakeBuiltinComponents();

// One anchor's initializer from names: filter options.filter.kind, solver options.solver_name,
// and `trigger`. `seed` feeds the parts that draw random numbers (RANSAC, stochastic NLopt); the
// truth, if known, serves the pdop_true oracle. Throws std::invalid_argument saying which name
// could not be built and why.
AnchorInitializer MakeInitializer(const Components& components, int anchor_id, const InitializerOptions& options,
                                  const std::string& trigger, std::uint64_t seed,
                                  const std::optional<Eigen::Vector3d>& p_world_anchor_true = std::nullopt);

}  // namespace anchorbench::estimator
