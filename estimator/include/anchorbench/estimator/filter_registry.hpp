#pragma once

#include <cstdint>
#include <string>

#include "anchorbench/estimator/consistency_filter.hpp"
#include "anchorbench/estimator/outlier_filter.hpp"
#include "anchorbench/estimator/ransac_solver.hpp"
#include "anchorbench/estimator/registry.hpp"

namespace anchorbench::estimator {

// Which filter runs (a FilterRegistry name) and the settings of the built-in ones.
struct FilterOptions {
  std::string kind = "consistency";      // none | consistency | ransac | your own
  ConsistencyFilterOptions consistency;  // kind consistency
  RansacOptions ransac;                  // kind ransac

  bool IsValid(std::string* why) const { return consistency.IsValid(why) && ransac.IsValid(why); }
};

// What a filter factory gets: the options and a seed for filters that draw random numbers.
struct FilterContext {
  FilterOptions options;
  std::uint64_t seed = 0;
};

using FilterRegistry = Registry<OutlierFilter, FilterContext>;

// none, consistency, ransac.
void RegisterBuiltinFilters(FilterRegistry& registry);

}  // namespace anchorbench::estimator
