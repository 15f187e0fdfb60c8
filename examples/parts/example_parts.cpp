#include "anchorbench/example_parts/example_parts.hpp"

namespace anchorbench::example_parts {

void RegisterTravelSpanTrigger(registry::TriggerRegistry& triggers);  // travel_span_trigger.cpp

void RegisterExampleParts(registry::Components& components) {
  RegisterTravelSpanTrigger(components.triggers);
}

}  // namespace anchorbench::example_parts
