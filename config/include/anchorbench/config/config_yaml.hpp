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
// Keys must be names, each at most once per mapping (both lines are named otherwise); a file must
// be a regular file of at most 1 MiB holding one YAML document, a mapping, that expands (aliases
// included) to at most 200,000 values; nesting is bounded by yaml-cpp's guard. An override needs
// a value ("KEY=" and "KEY=null" are refused).
YAML::Node LoadConfigYaml(const std::string& path, const std::vector<std::string>& overrides);
// The same from text; `source` names it in messages and anchors a relative `base:`.
YAML::Node LoadConfigYamlText(const std::string& text, const std::string& source,
                              const std::vector<std::string>& overrides);

// A config file read once with its bases laid under it, before any override: what the many
// evaluations of one experiment (a calibration's) start from, so that none reads the disk again.
struct ConfigDocument {
  std::string source;  // the file, as messages name it
  YAML::Node root;
};
ConfigDocument ReadConfigDocument(const std::string& path);
// The same from text; `source` names it and anchors a relative `base:`.
ConfigDocument ParseConfigDocument(const std::string& text, const std::string& source);
// A copy of the document with `overrides` applied (the document is left as it was).
YAML::Node WithOverrides(const ConfigDocument& document, const std::vector<std::string>& overrides);

// Every file reading `path` reads: the file itself, then its base, its base's base, ... (what a
// command must never overwrite or delete).
std::vector<std::string> ConfigFiles(const std::string& path);

}  // namespace anchorbench::config
