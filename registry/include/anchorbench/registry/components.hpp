#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/estimator/anchor_initializer.hpp"
#include "anchorbench/estimator/certified_trigger.hpp"
#include "anchorbench/estimator/init_trigger.hpp"
#include "anchorbench/estimator/outlier_filter.hpp"
#include "anchorbench/estimator/robust_kernel.hpp"
#include "anchorbench/estimator/solver.hpp"
#include "anchorbench/schema/estimator_config.hpp"
#include "anchorbench/sim/environment_model.hpp"
#include "anchorbench/registry/registry.hpp"

namespace anchorbench::registry {

// What a solver factory gets: the configured LS/NLS options (kernel scale, tolerances, ...), a
// seed for solvers that draw random numbers (one per anchor attempt, so results repeat), and the
// shared kernel tables (may be null: a solver then builds its own).
struct SolverContext {
  estimator::AnchorSolverOptions options;
  std::uint64_t seed = 0;
  estimator::LogPartitionTables* tables = nullptr;
};

// What a filter factory gets: the options and a seed for filters that draw random numbers.
struct FilterContext {
  schema::FilterConfig options;
  std::uint64_t seed = 0;
};

// What a trigger factory gets. The solver is the one the anchor is initialized with (before any
// batch filter wraps it), for triggers that look at its estimate. The reference position is for
// evaluation triggers only (eval's oracles): the anchor's true or surveyed position where the
// caller knows it. No built-in trigger of the estimator reads it.
struct TriggerContext {
  schema::TriggerConfig options;
  estimator::AnchorSolverOptions solver_options;  // the anchor's, its height prior included
  std::shared_ptr<const estimator::Solver> solver;
  std::optional<Eigen::Vector3d> p_world_anchor_reference;
  // The anchor's initializer options (its mirror check, with the height prior, and covariance)
  // and the certificate's, for triggers that judge an estimate as the initializer reports it.
  estimator::InitializerOptions initializer;
  estimator::CertificateOptions certificate;
  // The anchor's online filter's travel bias (OutlierFilter::TravelBias). The filter is owned by
  // the initializer that owns the trigger, so it outlives every call.
  estimator::TravelBias travel_bias;
};

// What an environment factory gets: nothing beyond its own options (RegisterWithOptions).
struct EnvironmentContext {};

using SolverRegistry = Registry<estimator::Solver, SolverContext>;
using FilterRegistry = Registry<estimator::OutlierFilter, FilterContext>;
using TriggerRegistry = Registry<estimator::InitTrigger, TriggerContext>;
// Simulated environments beside the tunnel and the hall, named by scenario.environment; their
// options are the section scenario.<name>.
using EnvironmentRegistry = Registry<sim::Environment, EnvironmentContext>;

// The registries of named parts an initializer is built from, owned by the caller, and the kernel
// tables the solvers built from them share.
struct Components {
  SolverRegistry solvers{"solver"};
  FilterRegistry filters{"filter"};
  TriggerRegistry triggers{"trigger"};
  EnvironmentRegistry environments{"environment"};
  std::shared_ptr<estimator::LogPartitionTables> tables = std::make_shared<estimator::LogPartitionTables>();

  // Whether every name of `config` is registered here; *why names the first that is not.
  bool Check(const schema::EstimatorConfig& config, std::string* why) const;
  // (name, its options) of every solver, filter and trigger that owns some (a name may repeat
  // across kinds: the config refuses that, since the two would share one section).
  std::vector<std::pair<std::string, const PartOptions*>> PartsWithOptions() const;
};

// ls_single, ls_double, lm_l2, lm_huber, lm_cauchy, lm_adaptive, nlopt:<ALGORITHM>.
void RegisterBuiltinSolvers(SolverRegistry& registry);
// none, consistency, ransac.
void RegisterBuiltinFilters(FilterRegistry& registry);
// pdop_closest_point, pdop_ls, pdop_nls, dop4_closest_point, dop4_confidence, hdop_closest_point,
// certified, fixed_window, sample_count, timeout.
void RegisterBuiltinTriggers(TriggerRegistry& registry);
// All three.
void RegisterBuiltins(Components& components);

// One anchor's initializer from names: config.filter.kind, config.solver and `trigger`. `seed`
// feeds the parts that draw random numbers (RANSAC); the reference position serves evaluation
// triggers and a height prior taken from the reference (HeightPriorConfig). Throws std::invalid_argument saying which name could not be built and why.
estimator::AnchorInitializer MakeInitializer(const Components& components, int anchor_id, const schema::EstimatorConfig& config,
                                             const std::string& trigger, std::uint64_t seed,
                                             const std::optional<Eigen::Vector3d>& p_world_anchor_reference = std::nullopt);

// The same with the trigger made by `make_trigger` from the context a named one gets (a study's
// probe, which no config names); it returns null with `why` set to refuse.
using TriggerMaker = std::function<std::unique_ptr<estimator::InitTrigger>(const TriggerContext&, std::string* why)>;
estimator::AnchorInitializer MakeInitializer(const Components& components, int anchor_id, const schema::EstimatorConfig& config,
                                             const TriggerMaker& make_trigger, std::uint64_t seed,
                                             const std::optional<Eigen::Vector3d>& p_world_anchor_reference = std::nullopt);

// One initializer per trigger of config.triggers, in that order (a FrontEnd's chains).
std::vector<estimator::AnchorInitializer> MakeChains(
    const Components& components, int anchor_id, const schema::EstimatorConfig& config, std::uint64_t seed,
    const std::optional<Eigen::Vector3d>& p_world_anchor_reference = std::nullopt);

}  // namespace anchorbench::registry
