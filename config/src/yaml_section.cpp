#include "anchorbench/config/yaml_section.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/schema/names.hpp"

namespace anchorbench::config {

using schema::InputError;
std::string YamlSection::Describe(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

YamlSection::YamlSection(const YAML::Node& node, std::string path, std::string file)
    : node_(node), path_(std::move(path)), file_(std::move(file)) {
  if (node_ && !node_.IsNull() && !node_.IsMap()) {
    throw InputError(file_ + ": key '" + path_ + "': expected a mapping, got " + Describe(node_));
  }
}

std::string YamlSection::KeyPath(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void YamlSection::Fail(std::string_view key, const std::string& message) const {
  throw InputError(file_ + ": key '" + KeyPath(key) + "': " + message);
}

void YamlSection::FailSection(const std::string& message) const {
  throw InputError(file_ + ": " + (path_.empty() ? std::string("top level") : "key '" + path_ + "'") + ": " + message);
}

void YamlSection::FailValidation(const std::string& why) const {
  const std::string key = why.substr(0, why.find(' '));
  if (key.size() < why.size() && Has(key)) Fail(key, why.substr(key.size() + 1) + ", got " + Describe(node_[key]));
  FailSection(why);
}

void YamlSection::Moved(std::string_view key, std::string_view section) {
  if (!node_[std::string(key)]) return;
  const std::size_t dot = path_.rfind('.');
  const std::string parent = dot == std::string::npos ? std::string() : path_.substr(0, dot + 1);
  Fail(key, "has moved: write it as " + parent + std::string(section) + "." + std::string(key));
}

bool YamlSection::Has(std::string_view key) const {
  asked_.emplace(key);
  return node_.IsMap() && node_[std::string(key)].IsDefined() && !node_[std::string(key)].IsNull();
}

YAML::Node YamlSection::Get(std::string_view key) {
  used_.emplace(key);
  return node_[std::string(key)];
}

void YamlSection::Number(std::string_view key, double& value, Bounds bounds) {
  if (!Has(key)) return;
  const YAML::Node n = Get(key);
  double parsed = 0.0;
  if (!n.IsScalar() || !YAML::convert<double>::decode(n, parsed)) Fail(key, "expected a number, got " + Describe(n));
  if (!std::isfinite(parsed)) Fail(key, "must be finite, got " + Describe(n));
  const bool below = bounds.min_exclusive ? parsed <= bounds.min : parsed < bounds.min;
  if ((below || parsed > bounds.max) && bounds.min == Bounds{}.min && bounds.max == Bounds{}.max) {
    std::ostringstream limit;
    limit << "must be a finite number of magnitude at most " << bounds.max << ", got ";
    Fail(key, limit.str() + Describe(n));
  }
  if (below || parsed > bounds.max) {
    std::ostringstream range;
    range << "must be " << (bounds.min_exclusive ? "> " : ">= ") << bounds.min;
    if (bounds.max < 1e300) range << " and <= " << bounds.max;
    Fail(key, range.str() + ", got " + Describe(n));
  }
  value = parsed;
}

void YamlSection::Integer(std::string_view key, int& value, int min, int max) {
  if (!Has(key)) return;
  const YAML::Node n = Get(key);
  int parsed = 0;
  if (!n.IsScalar() || !YAML::convert<int>::decode(n, parsed)) Fail(key, "expected an integer, got " + Describe(n));
  if (parsed < min || parsed > max) {
    Fail(key, "must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " + Describe(n));
  }
  value = parsed;
}

void YamlSection::Unsigned(std::string_view key, std::uint64_t& value, std::uint64_t max) {
  if (!Has(key)) return;
  const YAML::Node n = Get(key);
  std::uint64_t parsed = 0;
  const std::string text = n.IsScalar() ? n.Scalar() : std::string();
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), parsed);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || parsed > max) {
    Fail(key, "expected a whole number from 0 to " + std::to_string(max) + ", got " + Describe(n));
  }
  value = parsed;
}

void YamlSection::Flag(std::string_view key, bool& value) {
  if (!Has(key)) return;
  const YAML::Node n = Get(key);
  bool parsed = false;
  if (!n.IsScalar() || !YAML::convert<bool>::decode(n, parsed)) Fail(key, "expected true or false, got " + Describe(n));
  value = parsed;
}

void YamlSection::Text(std::string_view key, std::string& value) {
  if (!Has(key)) return;
  const YAML::Node n = Get(key);
  if (!n.IsScalar()) Fail(key, "expected text, got " + Describe(n));
  value = n.Scalar();
}

void YamlSection::Label(std::string_view key, std::string& value) {
  if (!Has(key)) return;
  Text(key, value);
  if (const std::string why = schema::NameProblem(value); !why.empty()) Fail(key, why);
}

void YamlSection::TextList(std::string_view key, std::vector<std::string>& values) {
  if (!Has(key)) return;
  const YAML::Node n = Get(key);
  if (!n.IsSequence()) Fail(key, "expected a list, got " + Describe(n));
  values.clear();
  for (const auto& item : n) {
    if (!item.IsScalar()) Fail(key, "expected a list of names, got " + Describe(item));
    values.push_back(item.Scalar());
  }
}

void YamlSection::VectorList(std::string_view key, std::vector<Eigen::Vector3d>& values) {
  if (!Has(key)) return;
  const YAML::Node n = Get(key);
  if (!n.IsSequence()) Fail(key, "expected a list of [x, y, z], got " + Describe(n));
  values.clear();
  for (const auto& item : n) {
    Eigen::Vector3d v;
    bool ok = item.IsSequence() && item.size() == 3;
    for (std::size_t i = 0; ok && i < 3; ++i) ok = item[i].IsScalar() && YAML::convert<double>::decode(item[i], v[i]);
    if (!ok || !v.allFinite()) Fail(key, "expected a list of [x, y, z] (metres), got an entry " + Describe(item));
    values.push_back(v);
  }
}

void YamlSection::TextMap(std::string_view key, std::vector<std::pair<std::string, std::string>>& entries) {
  if (!Has(key)) return;
  const YAML::Node n = Get(key);
  if (!n.IsMap()) Fail(key, "expected a mapping, got " + Describe(n));
  entries.clear();
  for (const auto& entry : n) {
    const std::string name = entry.first.as<std::string>();
    std::string text;
    if (entry.second.IsScalar()) {
      text = entry.second.Scalar();
    } else if (entry.second.IsSequence()) {
      for (const auto& item : entry.second) {
        if (!item.IsScalar()) Fail(std::string(key) + "." + name, "expected values, got " + Describe(item));
        text += (text.empty() ? "" : ",") + item.Scalar();
      }
    } else {
      Fail(std::string(key) + "." + name, "expected a value, a list or a range, got " + Describe(entry.second));
    }
    entries.emplace_back(name, text);
  }
}

void YamlSection::PartOptions(std::map<std::string, registry::OptionValues>& values,
                              const std::vector<std::string>& named, const OwnedOptions& parts) {
  std::set<std::string, std::less<>> seen;
  for (const auto& [part, options] : parts) {
    if (!seen.insert(part).second) FailSection("two parts named '" + part + "' own options: they would share one section");
    if (asked_.contains(part)) FailSection("the part '" + part + "' owns options but has the name of a key of this section");
    if (!Has(part)) continue;
    Section(part, [&, part = part, options = options](YamlSection& own) {
      registry::OptionValues& set = values[part];
      for (const registry::OptionSpec& spec : options->specs) {
        if (!own.Has(spec.key)) continue;
        double value = spec.default_value;
        own.Number(spec.key, value);
        set[spec.key] = value;
      }
      std::string why;
      if (!options->check(set, &why)) own.FailValidation(why);
    });
  }
  for (const auto& [part, options] : parts) {
    if (std::find(named.begin(), named.end(), part) == named.end()) continue;
    for (const registry::OptionSpec& spec : options->specs) values[part].try_emplace(spec.key, spec.default_value);
  }
}

void YamlSection::Finish() const {
  if (!node_.IsMap()) return;
  for (const auto& entry : node_) {
    const std::string key = entry.first.as<std::string>();
    if (used_.contains(key)) continue;
    if (asked_.contains(key)) Fail(key, "no value (give one, or remove the key to keep the default)");
    Fail(key, "unknown key");
  }
}

}  // namespace anchorbench::config
