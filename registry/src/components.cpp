#include "anchorbench/registry/components.hpp"

#include <stdexcept>

namespace anchorbench::registry {

bool Components::Check(const schema::EstimatorConfig& config, std::string* why) const {
  if (!solvers.Knows(config.solver, why) || !filters.Knows(config.filter.kind, why)) return false;
  for (const std::string& trigger : config.triggers) {
    if (!triggers.Knows(trigger, why)) return false;
  }
  return true;
}

std::vector<std::pair<std::string, const PartOptions*>> Components::PartsWithOptions() const {
  std::vector<std::pair<std::string, const PartOptions*>> parts = solvers.PartsWithOptions();
  for (auto& part : filters.PartsWithOptions()) parts.push_back(std::move(part));
  for (auto& part : triggers.PartsWithOptions()) parts.push_back(std::move(part));
  return parts;
}

void RegisterBuiltins(Components& components) {
  RegisterBuiltinSolvers(components.solvers);
  RegisterBuiltinFilters(components.filters);
  RegisterBuiltinTriggers(components.triggers);
}

estimator::AnchorInitializer MakeInitializer(const Components& components, int anchor_id, const schema::EstimatorConfig& config,
                                             const std::string& trigger, std::uint64_t seed,
                                             const std::optional<Eigen::Vector3d>& p_world_anchor_reference) {
  return MakeInitializer(
      components, anchor_id, config,
      [&](const TriggerContext& context, std::string* why) {
        return components.triggers.Create(trigger, context, why, ValuesOf(config.part_options, trigger));
      },
      seed, p_world_anchor_reference);
}

estimator::AnchorInitializer MakeInitializer(const Components& components, int anchor_id, const schema::EstimatorConfig& config,
                                             const TriggerMaker& make_trigger, std::uint64_t seed,
                                             const std::optional<Eigen::Vector3d>& p_world_anchor_reference) {
  std::string why;
  // The anchor's own height prior goes to its solver, from which the height check and the
  // certificate read it (Solver::height_prior).
  estimator::AnchorSolverOptions solver_options = config.solver_options;
  solver_options.height_prior = config.height_prior.For(anchor_id, p_world_anchor_reference);
  const estimator::InitializerOptions& initializer_options = config.initializer;
  std::shared_ptr<const estimator::Solver> solver =
      components.solvers.Create(config.solver, {solver_options, seed, components.tables.get()}, &why,
                                ValuesOf(config.part_options, config.solver));
  if (!solver) throw std::invalid_argument(why);
  if (solver_options.scale.estimate) solver = std::make_shared<estimator::ScaledSolver>(solver, solver_options.scale);
  std::unique_ptr<estimator::OutlierFilter> filter =
      components.filters.Create(config.filter.kind, {config.filter, seed}, &why, ValuesOf(config.part_options, config.filter.kind));
  if (!filter) throw std::invalid_argument(why);
  const estimator::OutlierFilter* online_filter = filter.get();
  std::unique_ptr<estimator::InitTrigger> made = make_trigger(
      {config.trigger, solver_options, solver, p_world_anchor_reference, initializer_options, config.certificate,
       [online_filter](double scale_m, double slack_m) { return online_filter->TravelBias(scale_m, slack_m); }},
      &why);
  if (!made) throw std::invalid_argument(why);
  return estimator::AnchorInitializer(anchor_id, initializer_options, std::move(filter), std::move(made),
                                      std::move(solver));
}

std::vector<estimator::AnchorInitializer> MakeChains(const Components& components, int anchor_id,
                                                     const schema::EstimatorConfig& config, std::uint64_t seed,
                                                     const std::optional<Eigen::Vector3d>& p_world_anchor_reference) {
  std::vector<estimator::AnchorInitializer> chains;
  for (const std::string& trigger : config.triggers) {
    chains.push_back(MakeInitializer(components, anchor_id, config, trigger, seed, p_world_anchor_reference));
  }
  return chains;
}

}  // namespace anchorbench::registry
