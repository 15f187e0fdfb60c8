#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "anchorbench/config/config_yaml.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/schema/experiment.hpp"

namespace anchorbench::config {

// Reads and validates an experiment file (configs/*.yaml; docs/config.md lists the keys); throws
// schema::InputError naming the file and key path. `overrides` are KEY=VALUE pairs (KEY a dotted
// path such as scenario.tunnel.width_m) applied to the YAML before validation, so an override is
// checked exactly like a value in the file. Part names (solver, filter, triggers) are checked
// against `components`, the caller's registries: a part of your own can be named in a file.
schema::ExperimentConfig LoadConfig(const std::string& path, const std::vector<std::string>& overrides,
                                    const registry::Components& components);

// The same from a config's text (a fuzzer's entry point); `source` names it and anchors `base:`.
schema::ExperimentConfig LoadConfigText(const std::string& text, const std::string& source,
                                        const std::vector<std::string>& overrides,
                                        const registry::Components& components);

// The same from a document read once (ReadConfigDocument): no file is read again.
schema::ExperimentConfig LoadConfig(const ConfigDocument& document, const std::vector<std::string>& overrides,
                                    const registry::Components& components);

// The `estimator` section of a file only (replay --config).
schema::EstimatorConfig LoadEstimatorConfig(const std::string& path, const registry::Components& components);

// The resolved configuration in the file schema: YAML text, and JSON (for manifests; the same
// tree, no text in between).
std::string ToYaml(const schema::ExperimentConfig& config);
nlohmann::ordered_json ToJson(const schema::ExperimentConfig& config);

}  // namespace anchorbench::config
