#pragma once

#include "anchorbench/eval/oracles.hpp"

namespace anchorbench::testing {

// The parts the anchorbench command offers (built-ins and oracles), built once for the tests.
// Tests that include this link anchorbench::eval.
inline const registry::Components& Parts() {
  static const registry::Components parts = eval::MakeComponentsWithOracles();
  return parts;
}

}  // namespace anchorbench::testing
