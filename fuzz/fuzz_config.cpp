// libFuzzer harness for the config loader: YAML text in, a validated experiment config or one
// schema::InputError out. A `base:` names files relative to a folder that does not exist.
#include <cstddef>
#include <cstdint>
#include <string>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/eval/oracles.hpp"
#include "anchorbench/schema/input_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const anchorbench::registry::Components components = anchorbench::eval::MakeComponentsWithOracles();
  try {
    anchorbench::config::LoadConfigText(std::string(reinterpret_cast<const char*>(data), size),
                                        "/nonexistent/fuzz.yaml", {}, components);
  } catch (const anchorbench::schema::InputError&) {
  }
  return 0;
}
