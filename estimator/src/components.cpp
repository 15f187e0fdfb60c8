#include "anchorbench/estimator/components.hpp"

#include <stdexcept>

namespace anchorbench::estimator {

void RegisterBuiltins(Components& components) {
  RegisterBuiltinSolvers(components.solvers);
  RegisterBuiltinFilters(components.filters);
  RegisterBuiltinTriggers(components.triggers);
}

Components MakeBuiltinComponents() {
  Components components;
  RegisterBuiltins(components);
  return components;
}

AnchorInitializer MakeInitializer(const Components& components, int anchor_id, const InitializerOptions& options,
                                  const std::string& trigger, std::uint64_t seed,
                                  const std::optional<Eigen::Vector3d>& p_world_anchor_true) {
  std::string why;
  std::shared_ptr<const Solver> solver = components.solvers.Create(options.solver_name, {options.solver, seed}, &why);
  if (!solver) throw std::invalid_argument(why);
  std::unique_ptr<OutlierFilter> filter = components.filters.Create(options.filter.kind, {options.filter, seed}, &why);
  if (!filter) throw std::invalid_argument(why);
  std::unique_ptr<InitTrigger> made =
      components.triggers.Create(trigger, {options.trigger, options.solver.ls, solver, p_world_anchor_true}, &why);
  if (!made) throw std::invalid_argument(why);
  return AnchorInitializer(anchor_id, options, std::move(filter), std::move(made), std::move(solver));
}

}  // namespace anchorbench::estimator
