#include "anchorbench/engine/plan.hpp"

#include <algorithm>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/hash.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::engine {

Plan::Plan(std::vector<schema::ExperimentConfig> experiments) : experiments_(std::move(experiments)) {
  std::string all_texts;
  for (std::size_t e = 0; e < experiments_.size(); ++e) {
    rows_.push_back(schema::RowsOf(experiments_[e]));
    const int units = static_cast<int>(rows_.back().size()) * experiments_[e].realizations;
    const int size = std::clamp((units + kChunksPerExperiment - 1) / kChunksPerExperiment, 1, kMaxChunkUnits);
    const int realizations = experiments_[e].realizations;
    for (int first = 0; first < units; first += size) {
      ChunkSpan span{static_cast<int>(e), first, std::min(first + size, units), 0};
      for (int unit = span.first_unit; unit < span.end_unit; ++unit) {
        const schema::RowConfig& row = rows_.back()[static_cast<std::size_t>(unit / realizations)];
        span.attempts += static_cast<long long>(row.scenario.NumAnchors()) * static_cast<long long>(row.estimator.triggers.size());
      }
      attempts_ += span.attempts;
      chunks_.push_back(span);
    }
    units_ += units;
    texts_.push_back(config::ToYaml(experiments_[e]));
    all_texts += texts_.back() + '\0';
  }
  identity_ = io::Fingerprint(all_texts);
}

Plan PlanFromTexts(const std::vector<std::string>& texts, const std::string& identity,
                   const registry::Components& components) {
  std::vector<schema::ExperimentConfig> experiments;
  for (std::size_t e = 0; e < texts.size(); ++e) {
    experiments.push_back(config::LoadConfigText(texts[e], "experiment " + std::to_string(e), {}, components));
  }
  Plan plan(std::move(experiments));
  if (plan.identity() != identity) {
    throw schema::InputError("the plan's configs read back as " + plan.identity() + ", not " + identity +
                         ": a config that does not survive its own YAML");
  }
  return plan;
}

}  // namespace anchorbench::engine
