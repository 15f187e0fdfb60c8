#pragma once

#include "anchorbench/registry/components.hpp"

namespace anchorbench::registry::testing {

// The built-in solvers, filters and triggers, built once for the tests.
inline const Components& Builtins() {
  static const Components components = [] {
    Components c;
    RegisterBuiltins(c);
    return c;
  }();
  return components;
}

}  // namespace anchorbench::registry::testing
