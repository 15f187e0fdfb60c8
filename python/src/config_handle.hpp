#pragma once
// An experiment config as Python holds it: the document it was read from (so a sweep lays its
// points over it without reading a file again) and the experiment it resolves to.

#include <string>
#include <vector>

#include "anchorbench/config/config_yaml.hpp"
#include "anchorbench/schema/experiment.hpp"

namespace anchorbench::python {

struct ConfigHandle {
  config::ConfigDocument document;
  schema::ExperimentConfig experiment;
  std::string source;                   // the file, or "<name>.yaml" for a dict
  std::vector<std::string> overrides;   // applied to the document: a sweep's points start from them
  std::vector<std::string> files;       // the files it was read from (its bases too): never replaced by save()
};

// From a file (its bases read once) or from YAML text, with KEY=VALUE overrides; InputError on bad input.
ConfigHandle LoadConfigFile(const std::string& path, const std::vector<std::string>& overrides);
ConfigHandle LoadConfigText(const std::string& text, const std::string& source, const std::vector<std::string>& overrides);

}  // namespace anchorbench::python
