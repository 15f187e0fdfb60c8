#pragma once
// A part's own options: a struct the part defines, and one function that names its fields for
// the config (read, validated, printed in the resolved config, listed by `anchorbench list`):
//
//   struct SpanOptions {
//     double span_m = 10.0;
//     bool IsValid(std::string* why) const;  // optional: limits beyond one field's own
//   };
//   template <typename V> void VisitOptions(V& v, SpanOptions& o) {
//     v.Number("span_m", o.span_m, "how far the tag must have travelled (m)");
//   }
//
// The part's config section is `estimator.<part name>` (`estimator.travel_span.span_m: 4`), a
// sweep axis like any key. The registry keeps the fields as OptionSpecs (key, default, whether
// whole, what it means) and builds the struct from the values a config set (PartOptions).

#include <cmath>
#include <concepts>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "anchorbench/schema/estimator_config.hpp"

namespace anchorbench::registry {

using OptionValues = schema::PartOptionValues;  // key -> value, as a config set them

struct OptionSpec {
  std::string key;
  double default_value = 0.0;
  bool whole = false;  // an integer field
  std::string description;
};

// What the registry keeps of an options struct: its fields, and its own check of a set of values.
struct PartOptions {
  std::vector<OptionSpec> specs;
  // Whether `values` (keys among specs, the rest at their defaults) make a valid struct; *why
  // says why not, naming the key.
  std::function<bool(const OptionValues& values, std::string* why)> check;

  const OptionSpec* Find(std::string_view key) const {
    for (const OptionSpec& spec : specs) {
      if (spec.key == key) return &spec;
    }
    return nullptr;
  }
};

// The values a config set for the part `name`, from a map of them by part (none: its defaults).
inline const OptionValues& ValuesOf(const std::map<std::string, OptionValues>& by_part, const std::string& name) {
  static const OptionValues kNone;
  const auto found = by_part.find(name);
  return found == by_part.end() ? kNone : found->second;
}

namespace detail {

// Lists an options struct's fields with the values a default-constructed one holds.
struct SpecCollector {
  std::vector<OptionSpec> specs;
  void Number(const char* key, double& value, const char* description) { specs.push_back({key, value, false, description}); }
  void Integer(const char* key, int& value, const char* description) {
    specs.push_back({key, static_cast<double>(value), true, description});
  }
};

// Sets an options struct's fields from the values a config set; the others keep their defaults.
struct ValueFiller {
  const OptionValues& values;
  void Number(const char* key, double& value, const char*) {
    if (const auto found = values.find(key); found != values.end()) value = found->second;
  }
  void Integer(const char* key, int& value, const char*) {
    if (const auto found = values.find(key); found != values.end()) value = static_cast<int>(found->second);
  }
};

template <typename Options>
concept SelfChecking = requires(const Options& options, std::string* why) {
  { options.IsValid(why) } -> std::convertible_to<bool>;
};

}  // namespace detail

// The struct a part's factory gets: its defaults, with the values the config set laid over.
template <typename Options>
Options OptionsFrom(const OptionValues& values) {
  Options options;
  detail::ValueFiller filler{values};
  VisitOptions(filler, options);
  return options;
}

// What the registry keeps of `Options` (found by VisitOptions through argument lookup).
template <typename Options>
PartOptions DescribeOptions() {
  Options defaults;
  detail::SpecCollector collector;
  VisitOptions(collector, defaults);
  PartOptions described{std::move(collector.specs), nullptr};
  described.check = [specs = described.specs](const OptionValues& values, std::string* why) {
    for (const OptionSpec& spec : specs) {
      const auto found = values.find(spec.key);
      if (found == values.end() || !spec.whole) continue;
      const double value = found->second;
      if (value != std::floor(value) || std::abs(value) > 2147483647.0) {
        if (why) *why = spec.key + " must be a whole number";
        return false;
      }
    }
    if constexpr (detail::SelfChecking<Options>) return OptionsFrom<Options>(values).IsValid(why);
    return true;
  };
  return described;
}

}  // namespace anchorbench::registry
