#pragma once

#include "anchorbench/eval/oracles.hpp"

namespace anchorbench::testing {

// The components the anchorbench command offers (built-ins and oracles), built once for the tests.
// Tests that include this link anchorbench::eval.
inline const registry::Components& AllComponents() {
  static const registry::Components components = eval::MakeComponentsWithOracles();
  return components;
}

}  // namespace anchorbench::testing
