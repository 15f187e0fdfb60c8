#pragma once
// Parts written as a user would write theirs, offered by the command line and the Python module
// beside the built-ins: each part is one file here, with one line in RegisterExampleParts.

#include "anchorbench/registry/components.hpp"

namespace anchorbench::example_parts {

// Every example part, into the caller's registries.
void RegisterExampleParts(registry::Components& components);

}  // namespace anchorbench::example_parts
