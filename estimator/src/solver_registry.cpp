#include "anchorbench/estimator/solver_registry.hpp"

#include <sstream>
#include <string_view>

namespace anchorbench::estimator {

void SolverRegistry::Register(const std::string& name, const std::string& description, Factory factory) {
  exact_[name] = {description, std::move(factory)};
}

void SolverRegistry::RegisterPrefix(const std::string& prefix, const std::string& description, Factory factory) {
  prefix_[prefix] = {description, std::move(factory)};
}

std::unique_ptr<Solver> SolverRegistry::Create(const std::string& name, const AnchorSolverOptions& options,
                                               std::uint64_t seed, std::string* why) const {
  if (const auto found = exact_.find(name); found != exact_.end()) return found->second.factory(name, options, seed, *this);
  for (const auto& [prefix, entry] : prefix_) {
    if (name.rfind(prefix, 0) == 0) {
      std::unique_ptr<Solver> solver = entry.factory(name, options, seed, *this);
      if (!solver && why) {  // a stream: GCC 12 warns falsely on string concatenation here (bug 105329)
        std::ostringstream message;
        message << "'" << std::string_view(name).substr(prefix.size()) << "' is not a known " << prefix << " choice";
        *why = message.str();
      }
      return solver;
    }
  }
  if (why) {
    std::ostringstream message;
    message << "unknown solver '" << name << "' (anchorbench list shows the choices)";
    *why = message.str();
  }
  return nullptr;
}

bool SolverRegistry::Knows(const std::string& name) const {
  std::string ignored;
  return Create(name, {}, 0, &ignored) != nullptr;
}

std::vector<std::pair<std::string, std::string>> SolverRegistry::List() const {
  std::vector<std::pair<std::string, std::string>> entries;
  for (const auto& [name, entry] : exact_) entries.emplace_back(name, entry.description);
  for (const auto& [prefix, entry] : prefix_) entries.emplace_back(prefix + "<NAME>", entry.description);
  return entries;
}

}  // namespace anchorbench::estimator
