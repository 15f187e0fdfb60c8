#pragma once

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace anchorbench::config {

// The YAML of an experiment file before it is parsed into structs:
// - `base: other.yaml` (relative to the file) loads that file first and lays this one over it:
//   mappings merge key by key, anything else (numbers, names, lists such as `rows`) replaces;
// - each override "a.b.c=value" then sets that value (a number indexes a list: rows.1...). An
//   override of a key outside `rows` also applies to every row that sets the same key itself, so
//   the overridden value holds everywhere.
// Throws InputError naming the file (and line, for YAML syntax errors).
YAML::Node LoadConfigYaml(const std::string& path, const std::vector<std::string>& overrides);

}  // namespace anchorbench::config
