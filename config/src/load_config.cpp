#include "anchorbench/config/load_config.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "anchorbench/config/config_yaml.hpp"
#include "anchorbench/config/yaml_section.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "visitors.hpp"

namespace anchorbench::config {
namespace {

bool IsWholeNumber(const std::string& text) {
  const std::size_t digits = text.find_first_not_of("0123456789", text.rfind('-', 0) == 0 ? 1 : 0);
  return digits == std::string::npos && text.size() > (text[0] == '-' ? 1u : 0u) && text.size() < 20 &&
         (text.size() == 1 || text[text[0] == '-' ? 1 : 0] != '0');
}

// YAML (as yaml-cpp holds it) to JSON: mappings in their order, lists, numbers and booleans as
// such, text as strings.
nlohmann::ordered_json YamlToJson(const YAML::Node& node) {
  if (node.IsMap()) {
    nlohmann::ordered_json object = nlohmann::ordered_json::object();
    for (const auto& entry : node) object[entry.first.as<std::string>()] = YamlToJson(entry.second);
    return object;
  }
  if (node.IsSequence()) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const YAML::Node& item : node) list.push_back(YamlToJson(item));
    return list;
  }
  const std::string scalar = node.Scalar();
  if (scalar == "true" || scalar == "false") return scalar == "true";
  // Whole numbers exactly (a seed above 2^53 would not survive a double).
  if (IsWholeNumber(scalar)) {
    return scalar[0] == '-' ? nlohmann::ordered_json(std::stoll(scalar)) : nlohmann::ordered_json(std::stoull(scalar));
  }
  double number = 0.0;
  if (YAML::convert<double>::decode(node, number) && std::isfinite(number)) return number;
  return scalar;
}

// The resolved configuration as a YAML tree in the file schema.
YAML::Node ToYamlNode(const schema::ExperimentConfig& config) {
  schema::ExperimentConfig copy = config;
  YAML::Node root(YAML::NodeType::Map);
  YamlWriter writer(root);
  const registry::Components no_parts;  // the writer does not check names
  visit::Experiment(writer, copy, no_parts);
  return root;
}

}  // namespace

namespace {

schema::ExperimentConfig FromYaml(const YAML::Node& root, const std::string& path,
                                  const registry::Components& components) {
  schema::ExperimentConfig config;
  config.name = std::filesystem::path(path).stem().string();
  if (root.IsMap() && root["experiment"]) {
    throw schema::InputError(path + ": is a calibration file (key 'experiment'), not an experiment: run it with "
                                "`anchorbench calibrate`");
  }
  YamlSection top(root, "", path);
  visit::Experiment(top, config, components);
  top.Finish();
  for (std::size_t i = 0; i < config.rows.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (config.rows[i].name == config.rows[j].name) {
        top.Fail("rows", "rows " + std::to_string(j) + " and " + std::to_string(i) + " are both named '" +
                             config.rows[i].name + "': each row's name must be its own (it keys the result tables)");
      }
    }
  }
  for (const std::string& name : config.only_rows) {
    const bool known =
        std::any_of(config.rows.begin(), config.rows.end(), [&](const schema::RowConfig& r) { return r.name == name; });
    if (!known) top.Fail("only_rows", "no row named '" + name + "'");
  }
  return config;
}

}  // namespace

schema::ExperimentConfig LoadConfig(const std::string& path, const std::vector<std::string>& overrides,
                                    const registry::Components& components) {
  return FromYaml(LoadConfigYaml(path, overrides), path, components);
}

schema::ExperimentConfig LoadConfig(const ConfigDocument& document, const std::vector<std::string>& overrides,
                                    const registry::Components& components) {
  return FromYaml(WithOverrides(document, overrides), document.source, components);
}

schema::ExperimentConfig LoadConfigText(const std::string& text, const std::string& source,
                                        const std::vector<std::string>& overrides,
                                        const registry::Components& components) {
  return FromYaml(LoadConfigYamlText(text, source, overrides), source, components);
}

schema::EstimatorConfig LoadEstimatorConfig(const std::string& path, const registry::Components& components) {
  return LoadConfig(path, {}, components).estimator;
}

std::string ToYaml(const schema::ExperimentConfig& config) {
  YAML::Emitter out;
  out << ToYamlNode(config);
  return out.c_str();
}

nlohmann::ordered_json ToJson(const schema::ExperimentConfig& config) { return YamlToJson(ToYamlNode(config)); }

}  // namespace anchorbench::config
