#include "anchorbench/config/config_yaml.hpp"

#include <charconv>
#include <filesystem>

#include "anchorbench/io/input_error.hpp"

namespace anchorbench::config {

using io::InputError;
namespace {

constexpr int kMaxBaseDepth = 8;  // a chain of `base:` files longer than this is taken to be a cycle

YAML::Node LoadFile(const std::string& path) {
  try {
    YAML::Node root = YAML::LoadFile(path);
    return root.IsNull() ? YAML::Node(YAML::NodeType::Map) : root;
  } catch (const YAML::BadFile&) {
    throw InputError(path + ": cannot open the config file");
  } catch (const YAML::ParserException& e) {
    throw InputError(path + ":" + std::to_string(e.mark.line + 1) + ": YAML syntax error: " + e.msg);
  }
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

YAML::Node LoadWithBase(const std::string& path, int depth) {
  YAML::Node root = LoadFile(path);
  if (!root.IsMap() || !root["base"]) return root;
  if (depth >= kMaxBaseDepth) throw InputError(path + ": key 'base': chain of base files too long (a cycle?)");
  const YAML::Node base_key = root["base"];
  if (!base_key.IsScalar()) throw InputError(path + ": key 'base': expected a file name");
  const std::filesystem::path base_path = std::filesystem::path(path).parent_path() / base_key.Scalar();
  root.remove("base");
  return Merge(LoadWithBase(base_path.string(), depth + 1), root);
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
  YAML::Node value;
  try {
    value = YAML::Load(assignment.substr(equals + 1));
  } catch (const YAML::Exception& e) {
    throw InputError("--set '" + assignment + "': " + e.msg);
  }
  Set(root, parts, value, assignment);
  if (parts.front() == "rows" || !root["rows"].IsSequence()) return;
  for (std::size_t i = 0; i < root["rows"].size(); ++i) {
    if (Has(root["rows"][i], parts)) Set(root["rows"][i], parts, value, assignment);
  }
}

}  // namespace

YAML::Node LoadConfigYaml(const std::string& path, const std::vector<std::string>& overrides) {
  YAML::Node root = LoadWithBase(path, 0);
  for (const std::string& assignment : overrides) ApplyOverride(root, assignment);
  return root;
}

}  // namespace anchorbench::config
