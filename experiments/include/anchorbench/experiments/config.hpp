#pragma once

#include <cstdint>
#include <string>

#include "anchorbench/estimator/anchor_initializer.hpp"
#include "anchorbench/experiments/yaml_section.hpp"
#include "anchorbench/sim/scenario.hpp"

namespace anchorbench::experiments {

// One experiment file (configs/*.yaml): a scenario to simulate and the estimator to run on it.
// Keys mirror the options structs field by field; docs/config.md lists them with units.
struct ExperimentConfig {
  std::string name;  // the file's stem, e.g. "tunnel"
  std::uint64_t seed = 1;
  sim::ScenarioOptions scenario;
  estimator::InitializerOptions estimator;  // strategy is ignored: gated and fixed both run
};

// Reads and validates the whole file; throws InputError naming the file and key path.
ExperimentConfig LoadConfig(const std::string& path);

// Section parsers. Absent keys keep the values already in `options`, so a section can be laid
// over defaults or over another configuration; unknown keys and invalid values throw InputError.
void ParseScenario(YamlSection& section, sim::ScenarioOptions& options);
void ParseEstimator(YamlSection& section, estimator::InitializerOptions& options);

// YAML text of a resolved configuration (for manifests), in the same schema.
std::string ToYaml(const ExperimentConfig& config);

}  // namespace anchorbench::experiments
