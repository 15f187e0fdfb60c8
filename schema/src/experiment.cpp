#include "anchorbench/schema/experiment.hpp"

#include <algorithm>

namespace anchorbench::schema {

std::vector<RowConfig> RowsOf(const ExperimentConfig& config) {
  if (config.rows.empty()) return {RowConfig{"base", config.scenario, config.estimator, std::nullopt}};
  if (config.only_rows.empty()) return config.rows;
  std::vector<RowConfig> selected;
  for (const RowConfig& row : config.rows) {
    if (std::find(config.only_rows.begin(), config.only_rows.end(), row.name) != config.only_rows.end()) {
      selected.push_back(row);
    }
  }
  return selected;
}

}  // namespace anchorbench::schema
