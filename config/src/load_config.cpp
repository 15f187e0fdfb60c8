#include "anchorbench/config/load_config.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "anchorbench/config/config_yaml.hpp"
#include "anchorbench/config/yaml_section.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "visitors.hpp"

namespace anchorbench::config {
namespace {

std::string JsonString(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

bool IsWholeNumber(const std::string& text) {
  const std::size_t digits = text.find_first_not_of("0123456789", text.rfind('-', 0) == 0 ? 1 : 0);
  return digits == std::string::npos && text.size() > (text[0] == '-' ? 1u : 0u) && text.size() < 20 &&
         (text.size() == 1 || text[text[0] == '-' ? 1 : 0] != '0');
}

// YAML (as yaml-cpp holds it) to JSON: mappings, lists, numbers and booleans as such, text quoted.
std::string YamlToJson(const YAML::Node& node, int indent) {
  const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
  if (node.IsMap()) {
    std::string out = "{";
    bool first = true;
    for (const auto& entry : node) {
      out += (first ? "\n" : ",\n") + pad + JsonString(entry.first.as<std::string>()) + ": " +
             YamlToJson(entry.second, indent + 2);
      first = false;
    }
    return out + "\n" + std::string(static_cast<std::size_t>(indent), ' ') + "}";
  }
  if (node.IsSequence()) {
    std::string out = "[";
    for (std::size_t i = 0; i < node.size(); ++i) out += (i ? ",\n" : "\n") + pad + YamlToJson(node[i], indent + 2);
    return out + "\n" + std::string(static_cast<std::size_t>(indent), ' ') + "]";
  }
  const std::string scalar = node.Scalar();
  double number = 0.0;
  if (scalar == "true" || scalar == "false") return scalar;
  if (IsWholeNumber(scalar)) return scalar;  // exactly (a seed above 2^53 would not survive a double)
  if (YAML::convert<double>::decode(node, number) && std::isfinite(number)) return io::FormatNumber(number);
  return JsonString(scalar);
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
  schema::ExperimentConfig copy = config;
  YAML::Node root(YAML::NodeType::Map);
  YamlWriter writer(root);
  const registry::Components no_parts;  // the writer does not check names
  visit::Experiment(writer, copy, no_parts);
  YAML::Emitter out;
  out << root;
  return out.c_str();
}

std::string ToJson(const schema::ExperimentConfig& config, int indent) {
  return YamlToJson(YAML::Load(ToYaml(config)), indent);
}

}  // namespace anchorbench::config
