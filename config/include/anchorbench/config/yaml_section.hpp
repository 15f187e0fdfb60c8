#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

#include "anchorbench/estimator/enum_names.hpp"
#include "anchorbench/registry/part_options.hpp"

namespace anchorbench::config {

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
  // A whole number in [0, max], read from its text (a seed: every value round-trips exactly).
  void Unsigned(std::string_view key, std::uint64_t& value, std::uint64_t max);
  void Flag(std::string_view key, bool& value);
  template <typename Enum, std::size_t N>
  void Choice(std::string_view key, Enum& value, const estimator::EnumNames<Enum, N>& names) {
    if (!Has(key)) return;
    const YAML::Node n = Get(key);
    if (!n.IsScalar() || !names.Parse(n.Scalar(), &value)) {
      Fail(key, "unknown value " + Describe(n) + " (choices: " + names.Choices() + ")");
    }
  }
  void Text(std::string_view key, std::string& value);
  // A name that goes into CSV and Markdown tables (a row's): printable, without ',', '"' or '|'.
  void Label(std::string_view key, std::string& value);
  void TextList(std::string_view key, std::vector<std::string>& values);
  // A registered name: known(name, &why) is a registry's Knows, so the message says why not.
  template <typename Known>
  void Name(std::string_view key, std::string& value, Known known) {
    if (!Has(key)) return;
    Text(key, value);
    std::string why;
    if (!known(value, &why)) Fail(key, why);
  }
  // A non-empty list of distinct registered names.
  template <typename Known>
  void NameList(std::string_view key, std::vector<std::string>& values, Known known) {
    if (!Has(key)) return;
    TextList(key, values);
    if (values.empty()) Fail(key, "expected at least one name (anchorbench list shows the choices)");
    for (std::size_t i = 0; i < values.size(); ++i) {
      std::string why;
      if (!known(values[i], &why)) Fail(key, why);
      for (std::size_t j = 0; j < i; ++j)
        if (values[j] == values[i]) Fail(key, "'" + values[i] + "' is listed twice");
    }
  }
  void VectorList(std::string_view key, std::vector<Eigen::Vector3d>& values);  // [[x, y, z], ...]
  // A mapping of free-form keys to a scalar or a list (joined with ','), in file order.
  void TextMap(std::string_view key, std::vector<std::pair<std::string, std::string>>& entries);
  template <typename Visit>
  void Section(std::string_view key, Visit visit) {
    // A key without a value (`scenario: ~`) is left unread, so Finish() refuses it as it refuses
    // `seed: ~`: never a silent reset of a whole section to its defaults.
    YamlSection child = Has(key) ? YamlSection(Get(key), KeyPath(key), file_)
                                 : YamlSection(YAML::Node(YAML::NodeType::Map), KeyPath(key), file_);
    visit(child);
    child.Finish();
  }
  // A section that may be absent: read into a fresh value only if present.
  template <typename T, typename Visit>
  void OptionalSection(std::string_view key, std::optional<T>& value, Visit visit) {
    if (!Has(key)) return;
    value.emplace();
    Section(key, [&](YamlSection& child) { visit(child, *value); });
  }
  // A list of mappings; each item starts as make_item() (e.g. a copy of the base) and is overlaid.
  template <typename T, typename Make, typename Visit>
  void List(std::string_view key, std::vector<T>& items, Make make_item, Visit visit) {
    if (!Has(key)) return;
    const YAML::Node list = Get(key);
    if (!list.IsSequence()) Fail(key, "expected a list, got " + Describe(list));
    items.clear();
    for (std::size_t i = 0; i < list.size(); ++i) {
      T item = make_item();
      YamlSection child(list[i], KeyPath(key) + "[" + std::to_string(i) + "]", file_);
      visit(child, item);
      child.Finish();
      items.push_back(std::move(item));
    }
  }
  // An options struct's IsValid, the one place its limits are checked. Its message starts with
  // the key it is about ("sigma_range_m must be >= 0"); where that is a key of this section, the
  // error names the key's path and value, otherwise the section.
  template <typename Options>
  void Check(const Options& options) const {
    std::string why;
    if (!options.IsValid(&why)) FailValidation(why);
  }

  // The sections of parts that own options (`parts`, from the registries), each key read as its
  // spec says and the whole checked by the part; then every part of `named` that owns options
  // gets the defaults of the keys the config did not set. Visited last in its section: a part
  // may not take the name of one of the section's own keys.
  using OwnedOptions = std::vector<std::pair<std::string, const registry::PartOptions*>>;
  void PartOptions(std::map<std::string, registry::OptionValues>& values, const std::vector<std::string>& named,
                   const OwnedOptions& parts);

  // A value derived from what was read (an environment the registry builds from its options):
  // resolve(&why) false fails on `key` with why. The writer has nothing to derive.
  template <typename Resolve>
  void Derive(std::string_view key, Resolve resolve) {
    std::string why;
    if (!resolve(&why)) Fail(key, why);
  }

  // A key that moved to the sibling section `section` (it keeps its name): present, it is refused
  // with the key's new path, so an old file fails in one line that says what to write instead.
  void Moved(std::string_view key, std::string_view section);

  bool Has(std::string_view key) const;  // present with a value (a key asked for is a known key)
  void Finish() const;  // throws on keys that were never read, and on known keys without a value
  [[noreturn]] void Fail(std::string_view key, const std::string& message) const;
  [[noreturn]] void FailSection(const std::string& message) const;
  [[noreturn]] void FailValidation(const std::string& why) const;
  std::string KeyPath(std::string_view key) const;
  static std::string Describe(const YAML::Node& node);

 private:
  YAML::Node Get(std::string_view key);

  YAML::Node node_;
  std::string path_;
  std::string file_;
  std::set<std::string, std::less<>> used_;
  mutable std::set<std::string, std::less<>> asked_;  // every key Has() was asked about
};

// The writing twin of YamlSection: the same visitors fill a YAML node (resolved configs in manifests).
class YamlWriter {
 public:
  explicit YamlWriter(YAML::Node node) : node_(node) {}

  void Number(std::string_view key, double& value, Bounds = {}) { node_[std::string(key)] = value; }
  void Integer(std::string_view key, int& value, int = 0, int = 0) { node_[std::string(key)] = value; }
  void Unsigned(std::string_view key, std::uint64_t& value, std::uint64_t) {
    node_[std::string(key)] = std::to_string(value);  // as text: yaml-cpp would go through a signed type
  }
  void Flag(std::string_view key, bool& value) { node_[std::string(key)] = value; }
  template <typename Enum, std::size_t N>
  void Choice(std::string_view key, Enum& value, const estimator::EnumNames<Enum, N>& names) {
    node_[std::string(key)] = std::string(names.Name(value));
  }
  void Text(std::string_view key, std::string& value) { node_[std::string(key)] = value; }
  void Label(std::string_view key, std::string& value) { Text(key, value); }
  void TextList(std::string_view key, std::vector<std::string>& values) {
    if (!values.empty()) node_[std::string(key)] = values;
  }
  template <typename Known>
  void Name(std::string_view key, std::string& value, Known) {
    Text(key, value);
  }
  template <typename Known>
  void NameList(std::string_view key, std::vector<std::string>& values, Known) {
    TextList(key, values);
  }
  void VectorList(std::string_view key, std::vector<Eigen::Vector3d>& values) {
    YAML::Node list(YAML::NodeType::Sequence);
    for (const Eigen::Vector3d& v : values) list.push_back(std::vector<double>{v.x(), v.y(), v.z()});
    node_[std::string(key)] = list;
  }
  void TextMap(std::string_view key, std::vector<std::pair<std::string, std::string>>& entries) {
    for (const auto& [name, text] : entries) node_[std::string(key)][name] = text;
  }
  template <typename Visit>
  void Section(std::string_view key, Visit visit) {
    YamlWriter child(node_[std::string(key)]);
    visit(child);
  }
  template <typename T, typename Visit>
  void OptionalSection(std::string_view key, std::optional<T>& value, Visit visit) {
    if (value) Section(key, [&](YamlWriter& child) { visit(child, *value); });
  }
  template <typename T, typename Make, typename Visit>
  void List(std::string_view key, std::vector<T>& items, Make, Visit visit) {
    if (items.empty()) return;
    YAML::Node list(YAML::NodeType::Sequence);
    for (T& item : items) {
      YAML::Node entry(YAML::NodeType::Map);
      YamlWriter child(entry);
      visit(child, item);
      list.push_back(entry);
    }
    node_[std::string(key)] = list;
  }
  template <typename Options>
  void Check(const Options&) const {}
  template <typename Resolve>
  void Derive(std::string_view, Resolve) {}
  void Moved(std::string_view, std::string_view) {}
  void PartOptions(std::map<std::string, registry::OptionValues>& values, const std::vector<std::string>&,
                   const YamlSection::OwnedOptions&) {
    for (const auto& [part, keys] : values) {
      for (const auto& [key, value] : keys) node_[part][key] = value;
    }
  }

 private:
  YAML::Node node_;
};

}  // namespace anchorbench::config
