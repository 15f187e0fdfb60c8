#include "anchorbench/config/config_yaml.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include <yaml-cpp/depthguard.h>

#include "anchorbench/schema/input_error.hpp"
#include "one_document.hpp"

namespace anchorbench::config {

using schema::InputError;
namespace {

constexpr int kMaxBaseDepth = 8;  // a chain of `base:` files longer than this is taken to be a cycle

constexpr std::uintmax_t kMaxConfigBytes = 1 << 20;  // configs are a few kB; a larger file is not one

std::string Line(const YAML::Mark& mark) { return std::to_string(mark.line + 1); }

// Every mapping's keys are names, each once (yaml-cpp keeps both of a repeated key and reads the
// first; a list or a mapping as a key would end as an internal error later).
void CheckKeys(const YAML::Node& node, const std::string& source) {
  if (node.IsSequence()) {
    for (const auto& item : node) CheckKeys(item, source);
    return;
  }
  if (!node.IsMap()) return;
  std::map<std::string, int> seen;
  for (const auto& entry : node) {
    if (!entry.first.IsScalar()) {
      throw InputError(source + ":" + Line(entry.first.Mark()) + ": a key must be a name, got " +
                       (entry.first.IsSequence() ? "a list" : entry.first.IsMap() ? "a mapping" : "nothing"));
    }
    const auto [first, inserted] = seen.emplace(entry.first.Scalar(), entry.first.Mark().line + 1);
    if (!inserted) {
      throw InputError(source + ":" + Line(entry.first.Mark()) + ": key '" + entry.first.Scalar() +
                       "' appears twice (lines " + std::to_string(first->second) + " and " + Line(entry.first.Mark()) + ")");
    }
    CheckKeys(entry.second, source);
  }
}

// Aliases let a small text stand for a huge tree (each `*a` repeats the whole of `&a`): the tree
// is counted, node by node, before anything walks it, and refused beyond this many. A config of
// the project has a few hundred; Table I's rows and the stress test's a few thousand.
constexpr long kMaxConfigNodes = 200000;

void CountNodes(const YAML::Node& node, long& budget, const std::string& source) {
  if (--budget < 0) {
    throw InputError(source + ": expands to more than " + std::to_string(kMaxConfigNodes) +
                     " values (aliases repeated inside aliases?): not a config");
  }
  if (node.IsMap()) {
    for (const auto& entry : node) {
      CountNodes(entry.first, budget, source);
      CountNodes(entry.second, budget, source);
    }
  } else if (node.IsSequence()) {
    for (const auto& item : node) CountNodes(item, budget, source);
  }
}

// The node budget holds for the only document: an alias bomb is refused before it is walked.
YAML::Node CheckedDocument(const std::string& text, const std::string& source) {
  YAML::Node document = OnlyDocument(text, source);
  long budget = kMaxConfigNodes;
  CountNodes(document, budget, source);
  return document;
}

// A config's text as a mapping of keys (an empty text is an empty mapping).
YAML::Node ParseText(const std::string& text, const std::string& source) {
  YAML::Node root;
  try {
    root = CheckedDocument(text, source);
  } catch (const YAML::DeepRecursion& e) {
    throw InputError(source + ":" + Line(e.mark) + ": nested deeper than the YAML reader allows (" +
                     std::to_string(e.depth()) + " levels)");
  } catch (const YAML::ParserException& e) {
    throw InputError(source + ":" + Line(e.mark) + ": YAML syntax error: " + e.msg);
  } catch (const YAML::Exception& e) {
    throw InputError(source + ": YAML error: " + e.msg);
  }
  if (root.IsNull()) return YAML::Node(YAML::NodeType::Map);
  if (!root.IsMap()) {
    throw InputError(source + ": expected a mapping of config keys (key: value lines), got " +
                     (root.IsSequence() ? "a list" : "'" + root.Scalar().substr(0, 40) + "'"));
  }
  CheckKeys(root, source);
  return root;
}

std::string ReadConfigFile(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) throw InputError(path + ": cannot open the config file");
  if (!std::filesystem::is_regular_file(path, error)) throw InputError(path + ": is not a config file (a folder?)");
  if (std::filesystem::file_size(path, error) > kMaxConfigBytes) throw InputError(path + ": more than 1 MiB: not a config");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw InputError(path + ": cannot read the config file");
  return text.str();
}

// Lays `over` onto `base`: mappings merge recursively, everything else replaces.
YAML::Node Merge(const YAML::Node& base, const YAML::Node& over) {
  if (!base.IsMap() || !over.IsMap()) return YAML::Clone(over);
  YAML::Node merged = YAML::Clone(base);
  for (const auto& entry : over) {
    const std::string key = entry.first.as<std::string>();
    merged[key] = merged[key].IsDefined() ? Merge(merged[key], entry.second) : YAML::Clone(entry.second);
  }
  return merged;
}

// The file `source` names as its base (relative to `source`'s folder), if any; the key is removed.
std::optional<std::string> TakeBase(YAML::Node& root, const std::string& source, int depth) {
  if (!root["base"]) return std::nullopt;
  if (depth >= kMaxBaseDepth) throw InputError(source + ": key 'base': chain of base files too long (a cycle?)");
  const YAML::Node base_key = root["base"];
  if (!base_key.IsScalar() || base_key.Scalar().empty()) throw InputError(source + ": key 'base': expected a file name");
  const std::string base_path = (std::filesystem::path(source).parent_path() / base_key.Scalar()).string();
  root.remove("base");
  return base_path;
}

// The text of `source` laid over its `base:` file, if it names one; `files` gets every base read.
YAML::Node WithBase(const std::string& text, const std::string& source, int depth, std::vector<std::string>* files) {
  YAML::Node root = ParseText(text, source);
  const std::optional<std::string> base_path = TakeBase(root, source, depth);
  if (!base_path) return root;
  if (files) files->push_back(*base_path);
  return Merge(WithBase(ReadConfigFile(*base_path), *base_path, depth + 1, files), root);
}

std::vector<std::string> SplitKey(const std::string& key) {
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const std::size_t dot = key.find('.', start);
    parts.push_back(key.substr(start, dot - start));
    if (dot == std::string::npos) return parts;
    start = dot + 1;
  }
}

// Sets the value at `parts` below `node`, creating mappings on the way (a number indexes a list).
void Set(YAML::Node node, const std::vector<std::string>& parts, const YAML::Node& value, const std::string& what) {
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string& part = parts[i];
    const bool last = i + 1 == parts.size();
    if (node.IsSequence()) {
      std::size_t index = 0;
      const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), index);
      if (ec != std::errc() || end != part.data() + part.size() || index >= node.size()) {
        throw InputError("--set '" + what + "': '" + part + "' is not an index of the list (0 to " +
                         std::to_string(node.size() - 1) + ")");
      }
      if (last) {
        node[index] = value;
        return;
      }
      node.reset(node[index]);
      continue;
    }
    if (node.IsDefined() && !node.IsNull() && !node.IsMap()) {
      throw InputError("--set '" + what + "': '" + parts[i - 1] + "' is not a section");
    }
    if (last) {
      node[part] = value;
      return;
    }
    if (!node[part].IsDefined() || node[part].IsNull()) node[part] = YAML::Node(YAML::NodeType::Map);
    node.reset(node[part]);
  }
}

bool Has(YAML::Node node, const std::vector<std::string>& parts) {
  for (const std::string& part : parts) {
    if (!node.IsMap() || !node[part]) return false;
    node.reset(node[part]);
  }
  return true;
}

void ApplyOverride(YAML::Node& root, const std::string& assignment) {
  const std::size_t equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw InputError("--set '" + assignment + "': expected KEY=VALUE, e.g. scenario.tunnel.width_m=12");
  }
  const std::vector<std::string> parts = SplitKey(assignment.substr(0, equals));
  const std::string what = "--set '" + assignment + "'";
  YAML::Node value;
  try {
    value = OnlyDocument(assignment.substr(equals + 1), what);
  } catch (const YAML::Exception& e) {
    throw InputError(what + ": " + e.msg);
  }
  if (!value.IsDefined() || value.IsNull()) throw InputError(what + ": no value (KEY=VALUE, e.g. " + parts.back() + "=1)");
  CheckKeys(value, what);
  Set(root, parts, value, assignment);
  if (parts.front() == "rows" || !root["rows"].IsSequence()) return;
  for (std::size_t i = 0; i < root["rows"].size(); ++i) {
    if (Has(root["rows"][i], parts)) Set(root["rows"][i], parts, value, assignment);
  }
}

}  // namespace

YAML::Node LoadConfigYaml(const std::string& path, const std::vector<std::string>& overrides) {
  return LoadConfigYamlText(ReadConfigFile(path), path, overrides);
}

YAML::Node LoadConfigYamlText(const std::string& text, const std::string& source,
                              const std::vector<std::string>& overrides) {
  YAML::Node root = WithBase(text, source, 0, nullptr);
  for (const std::string& assignment : overrides) ApplyOverride(root, assignment);
  return root;
}

ConfigDocument ReadConfigDocument(const std::string& path) {
  return {path, WithBase(ReadConfigFile(path), path, 0, nullptr)};
}

ConfigDocument ParseConfigDocument(const std::string& text, const std::string& source) {
  return {source, WithBase(text, source, 0, nullptr)};
}

YAML::Node WithOverrides(const ConfigDocument& document, const std::vector<std::string>& overrides) {
  YAML::Node root = YAML::Clone(document.root);
  for (const std::string& assignment : overrides) ApplyOverride(root, assignment);
  return root;
}

std::vector<std::string> ConfigFiles(const std::string& path) {
  std::vector<std::string> files = {path};
  WithBase(ReadConfigFile(path), path, 0, &files);
  return files;
}

}  // namespace anchorbench::config
