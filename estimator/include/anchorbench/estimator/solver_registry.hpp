#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/solver.hpp"

namespace anchorbench::estimator {

// Named solver factories. The caller owns the registry and fills it (RegisterBuiltinSolvers, then
// its own), so nothing registers itself behind the linker's back and there is no global state.
// A factory gets the configured LS/NLS options (kernel scale, tolerances, ...) and a seed for
// solvers that draw random numbers; a prefix entry ("nlopt:") serves every name it starts.
class SolverRegistry {
 public:
  // The registry itself is passed in, so a wrapper (ransac:<SOLVER>) can build the solver it wraps.
  using Factory = std::function<std::unique_ptr<Solver>(const std::string& name, const AnchorSolverOptions& options,
                                                        std::uint64_t seed, const SolverRegistry& registry)>;

  void Register(const std::string& name, const std::string& description, Factory factory);
  // For names that start with `prefix` (e.g. "nlopt:" + an NLopt algorithm).
  void RegisterPrefix(const std::string& prefix, const std::string& description, Factory factory);

  // nullptr if the name is unknown (or the factory rejects it; *why says why).
  std::unique_ptr<Solver> Create(const std::string& name, const AnchorSolverOptions& options, std::uint64_t seed,
                                 std::string* why = nullptr) const;
  bool Knows(const std::string& name) const;
  // (name, description), sorted by name; prefix entries read "prefix:<NAME>".
  std::vector<std::pair<std::string, std::string>> List() const;

 private:
  struct Entry {
    std::string description;
    Factory factory;
  };
  std::map<std::string, Entry> exact_;
  std::map<std::string, Entry> prefix_;
};

// ls_single, ls_double, lm_l2, lm_huber, lm_cauchy, lm_adaptive, nlopt:<ALGORITHM>, ransac:<SOLVER>.
void RegisterBuiltinSolvers(SolverRegistry& registry);

}  // namespace anchorbench::estimator
