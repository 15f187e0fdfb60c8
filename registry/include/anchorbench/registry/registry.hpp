#pragma once

#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "anchorbench/registry/part_options.hpp"

namespace anchorbench::registry {

// Named factories for one kind of part (solvers, filters, triggers). The caller owns the
// registry and fills it (RegisterBuiltins, then its own entries), so nothing registers itself
// behind the linker's back and there is no global state. A factory gets the name it was asked
// for and a Context (the configured options, a seed, ...). A prefix entry ("nlopt:") serves
// every name that starts with it; its `accepts` function says, cheaply and without building
// anything, which of those names exist. A factory that cannot serve its context (an oracle
// trigger without the truth) throws std::invalid_argument saying why. A part registered with
// RegisterWithOptions owns an options struct (part_options.hpp): its factory gets the struct.
template <typename Product, typename Context>
class Registry {
 public:
  using Factory = std::function<std::unique_ptr<Product>(const std::string& name, const Context& context)>;
  // Whether the part after the prefix exists; *why says why not.
  using Accepts = std::function<bool(const std::string& rest, std::string* why)>;

  // `noun` names the kind in messages ("solver", "filter", "trigger").
  explicit Registry(std::string noun) : noun_(std::move(noun)) {}

  void Register(const std::string& name, const std::string& description, Factory factory) {
    exact_[name] = {description, Ignoring(std::move(factory)), nullptr, std::nullopt};
  }
  // A part with options of its own: make(options, context) with `Options` built from the values
  // the config set (OptionsFrom), its other fields at their defaults.
  template <typename Options, typename Make>
  void RegisterWithOptions(const std::string& name, const std::string& description, Make make) {
    exact_[name] = {description,
                    [make = std::move(make)](const std::string&, const Context& context, const OptionValues& values) {
                      return std::unique_ptr<Product>(make(OptionsFrom<Options>(values), context));
                    },
                    nullptr, DescribeOptions<Options>()};
  }
  void RegisterPrefix(const std::string& prefix, const std::string& description, Factory factory, Accepts accepts) {
    prefix_[prefix] = {description, Ignoring(std::move(factory)), std::move(accepts), std::nullopt};
  }

  // Whether `name` can be built (given a context the factory accepts); *why says why not.
  bool Knows(const std::string& name, std::string* why = nullptr) const { return Find(name, why) != nullptr; }

  // nullptr if the name is unknown or its factory refuses the context; *why then says why.
  // `values` are the part's own options as the config set them (EstimatorConfig::part_options).
  std::unique_ptr<Product> Create(const std::string& name, const Context& context, std::string* why = nullptr,
                                  const OptionValues& values = {}) const {
    const Entry* entry = Find(name, why);
    if (!entry) return nullptr;
    try {
      return entry->factory(name, context, values);
    } catch (const std::invalid_argument& e) {
      if (why) *why = Message({noun_, " '", name, "': ", e.what()});
      return nullptr;
    }
  }

  // The options a part owns, or null (a part without, a prefix entry, an unknown name).
  const PartOptions* OptionsOf(const std::string& name) const {
    const auto found = exact_.find(name);
    return found != exact_.end() && found->second.options ? &*found->second.options : nullptr;
  }
  // (name, its options) of every part that owns some, sorted by name.
  std::vector<std::pair<std::string, const PartOptions*>> PartsWithOptions() const {
    std::vector<std::pair<std::string, const PartOptions*>> parts;
    for (const auto& [name, entry] : exact_) {
      if (entry.options) parts.emplace_back(name, &*entry.options);
    }
    return parts;
  }

  // (name, description), sorted by name; prefix entries read "prefix<NAME>".
  std::vector<std::pair<std::string, std::string>> List() const {
    std::vector<std::pair<std::string, std::string>> entries;
    for (const auto& [name, entry] : exact_) entries.emplace_back(name, entry.description);
    for (const auto& [prefix, entry] : prefix_) entries.emplace_back(prefix + "<NAME>", entry.description);
    return entries;
  }

 private:
  using Build = std::function<std::unique_ptr<Product>(const std::string& name, const Context& context,
                                                       const OptionValues& values)>;
  struct Entry {
    std::string description;
    Build factory;
    Accepts accepts;                     // prefix entries only
    std::optional<PartOptions> options;  // parts registered with options of their own
  };

  static Build Ignoring(Factory factory) {
    return [factory = std::move(factory)](const std::string& name, const Context& context, const OptionValues&) {
      return factory(name, context);
    };
  }

  const Entry* Find(const std::string& name, std::string* why) const {
    if (const auto found = exact_.find(name); found != exact_.end()) return &found->second;
    for (const auto& [prefix, entry] : prefix_) {
      if (name.rfind(prefix, 0) != 0) continue;
      std::string reason;
      if (entry.accepts(name.substr(prefix.size()), &reason)) return &entry;
      if (why) *why = Message({noun_, " '", name, "': ", reason});
      return nullptr;
    }
    if (why) *why = Message({"unknown ", noun_, " '", name, "' (anchorbench list shows the choices)"});
    return nullptr;
  }

  // Joined with append: GCC 12 warns falsely on chains of operator+ here (bug 105329).
  static std::string Message(std::initializer_list<std::string_view> parts) {
    std::string text;
    for (std::string_view part : parts) text.append(part);
    return text;
  }

  std::string noun_;
  std::map<std::string, Entry> exact_;
  std::map<std::string, Entry> prefix_;
};

}  // namespace anchorbench::registry
