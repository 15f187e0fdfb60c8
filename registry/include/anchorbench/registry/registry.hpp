#pragma once

#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace anchorbench::registry {

// Named factories for one kind of part (solvers, filters, triggers). The caller owns the
// registry and fills it (RegisterBuiltins, then its own entries), so nothing registers itself
// behind the linker's back and there is no global state. A factory gets the name it was asked
// for and a Context (the configured options, a seed, ...). A prefix entry ("nlopt:") serves
// every name that starts with it; its `accepts` function says, cheaply and without building
// anything, which of those names exist. A factory that cannot serve its context (an oracle
// trigger without the truth) throws std::invalid_argument saying why.
template <typename Product, typename Context>
class Registry {
 public:
  using Factory = std::function<std::unique_ptr<Product>(const std::string& name, const Context& context)>;
  // Whether the part after the prefix exists; *why says why not.
  using Accepts = std::function<bool(const std::string& rest, std::string* why)>;

  // `noun` names the kind in messages ("solver", "filter", "trigger").
  explicit Registry(std::string noun) : noun_(std::move(noun)) {}

  void Register(const std::string& name, const std::string& description, Factory factory) {
    exact_[name] = {description, std::move(factory), nullptr};
  }
  void RegisterPrefix(const std::string& prefix, const std::string& description, Factory factory, Accepts accepts) {
    prefix_[prefix] = {description, std::move(factory), std::move(accepts)};
  }

  // Whether `name` can be built (given a context the factory accepts); *why says why not.
  bool Knows(const std::string& name, std::string* why = nullptr) const { return Find(name, why) != nullptr; }

  // nullptr if the name is unknown or its factory refuses the context; *why then says why.
  std::unique_ptr<Product> Create(const std::string& name, const Context& context, std::string* why = nullptr) const {
    const Entry* entry = Find(name, why);
    if (!entry) return nullptr;
    try {
      return entry->factory(name, context);
    } catch (const std::invalid_argument& e) {
      if (why) *why = Message({noun_, " '", name, "': ", e.what()});
      return nullptr;
    }
  }

  // (name, description), sorted by name; prefix entries read "prefix<NAME>".
  std::vector<std::pair<std::string, std::string>> List() const {
    std::vector<std::pair<std::string, std::string>> entries;
    for (const auto& [name, entry] : exact_) entries.emplace_back(name, entry.description);
    for (const auto& [prefix, entry] : prefix_) entries.emplace_back(prefix + "<NAME>", entry.description);
    return entries;
  }

 private:
  struct Entry {
    std::string description;
    Factory factory;
    Accepts accepts;  // prefix entries only
  };

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
