#pragma once

#include <functional>
#include <set>
#include <string>
#include <string_view>

#include <yaml-cpp/yaml.h>

namespace anchorbench::experiments {

struct Bounds {
  double min = -1e300;
  double max = 1e300;
  bool min_exclusive = false;
};

// Reads a YAML mapping field by field with the key path in every error. Absent keys keep the
// value they had (the options structs' defaults, or a base configuration being overlaid);
// Finish() rejects keys nobody asked for. The config visitors (config.cpp) drive it, and drive
// YamlWriter the same way, so every key is listed once.
class YamlSection {
 public:
  YamlSection(const YAML::Node& node, std::string path, std::string file);

  void Number(std::string_view key, double& value, Bounds bounds = {});
  void Integer(std::string_view key, int& value, int min = -2147483647, int max = 2147483647);
  void Flag(std::string_view key, bool& value);
  template <typename Enum, typename Parse, typename Name>
  void Choice(std::string_view key, Enum& value, Parse parse, Name /*to_string*/, std::string_view choices) {
    if (!Has(key)) return;
    const YAML::Node n = Get(key);
    if (!n.IsScalar() || !parse(n.Scalar(), &value)) {
      Fail(key, "unknown value " + Describe(n) + " (choices: " + std::string(choices) + ")");
    }
  }
  template <typename Visit>
  void Section(std::string_view key, Visit visit) {
    YamlSection child = Has(key) ? YamlSection(Get(key), KeyPath(key), file_)
                                 : YamlSection(YAML::Node(YAML::NodeType::Map), KeyPath(key), file_);
    used_.emplace(key);
    visit(child);
    child.Finish();
  }
  // A cross-field check (an options struct's IsValid), reported against this section.
  template <typename Options>
  void Check(const Options& options) const {
    std::string why;
    if (!options.IsValid(&why)) FailSection(why);
  }

  bool Has(std::string_view key) const;
  void Finish() const;  // throws on keys that were never read
  [[noreturn]] void Fail(std::string_view key, const std::string& message) const;
  [[noreturn]] void FailSection(const std::string& message) const;
  std::string KeyPath(std::string_view key) const;
  static std::string Describe(const YAML::Node& node);

 private:
  YAML::Node Get(std::string_view key);

  YAML::Node node_;
  std::string path_;
  std::string file_;
  std::set<std::string, std::less<>> used_;
};

// The writing twin of YamlSection: the same visitors fill a YAML node (resolved configs in manifests).
class YamlWriter {
 public:
  explicit YamlWriter(YAML::Node node) : node_(node) {}

  void Number(std::string_view key, double& value, Bounds = {}) { node_[std::string(key)] = value; }
  void Integer(std::string_view key, int& value, int = 0, int = 0) { node_[std::string(key)] = value; }
  void Flag(std::string_view key, bool& value) { node_[std::string(key)] = value; }
  template <typename Enum, typename Parse, typename Name>
  void Choice(std::string_view key, Enum& value, Parse, Name to_string, std::string_view) {
    node_[std::string(key)] = std::string(to_string(value));
  }
  template <typename Visit>
  void Section(std::string_view key, Visit visit) {
    YamlWriter child(node_[std::string(key)]);
    visit(child);
  }
  template <typename Options>
  void Check(const Options&) const {}

 private:
  YAML::Node node_;
};

}  // namespace anchorbench::experiments
