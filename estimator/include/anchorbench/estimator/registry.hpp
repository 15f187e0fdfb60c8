#pragma once

#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace anchorbench::estimator {

// Named factories for one kind of component (solvers, filters, triggers). The caller owns the
// registry and fills it (RegisterBuiltins, then its own entries), so nothing registers itself
// behind the linker's back and there is no global state. A factory gets the name it was asked
// for and a Context (the configured options, a seed, ...); a prefix entry ("nlopt:") serves every
// name that starts with it and refuses an unknown one by returning nullptr. A factory that cannot
// serve its context (pdop_true without the truth) throws std::invalid_argument saying why.
template <typename Product, typename Context>
class Registry {
 public:
  using Factory = std::function<std::unique_ptr<Product>(const std::string& name, const Context& context)>;

  // `noun` names the kind in messages ("solver", "filter", "trigger").
  explicit Registry(std::string noun) : noun_(std::move(noun)) {}

  void Register(const std::string& name, const std::string& description, Factory factory) {
    exact_[name] = {description, std::move(factory)};
  }
  void RegisterPrefix(const std::string& prefix, const std::string& description, Factory factory) {
    prefix_[prefix] = {description, std::move(factory)};
  }

  // nullptr if the name is unknown or its factory refuses the context; *why then says why.
  std::unique_ptr<Product> Create(const std::string& name, const Context& context, std::string* why = nullptr) const {
    const Entry* entry = nullptr;
    std::string refusal;
    if (const auto found = exact_.find(name); found != exact_.end()) {
      entry = &found->second;
    } else {
      for (const auto& [prefix, candidate] : prefix_) {
        if (name.rfind(prefix, 0) != 0) continue;
        entry = &candidate;
        refusal = Message({"'", name.substr(prefix.size()), "' is not a known ", prefix, " choice"});
      }
    }
    if (!entry) refusal = Message({"unknown ", noun_, " '", name, "' (anchorbench list shows the choices)"});
    std::unique_ptr<Product> product;
    try {
      if (entry) product = entry->factory(name, context);
    } catch (const std::invalid_argument& e) {
      refusal = Message({noun_, " '", name, "': ", e.what()});
    }
    if (!product && why) *why = refusal;
    return product;
  }

  // Whether `name` is registered; a prefixed name is checked by its factory on a default context.
  bool Knows(const std::string& name) const {
    if (exact_.count(name) != 0) return true;
    std::string ignored;
    return Create(name, Context{}, &ignored) != nullptr;
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
  };

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

}  // namespace anchorbench::estimator
