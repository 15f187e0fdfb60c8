#include "anchorbench/example_parts/example_parts.hpp"

namespace anchorbench::example_parts {

void RegisterTravelSpanTrigger(registry::TriggerRegistry& triggers);                // travel_span_trigger.cpp
void RegisterCeilingGridEnvironment(registry::EnvironmentRegistry& environments);  // ceiling_grid_environment.cpp

void RegisterExampleParts(registry::Components& components) {
  RegisterTravelSpanTrigger(components.triggers);
  RegisterCeilingGridEnvironment(components.environments);
}

}  // namespace anchorbench::example_parts
