#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "anchorbench/schema/estimator_config.hpp"
#include "anchorbench/schema/exploration.hpp"
#include "anchorbench/schema/navigation.hpp"
#include "anchorbench/schema/pdop_study.hpp"
#include "anchorbench/sim/scenario.hpp"

namespace anchorbench::schema {

// A published table row to compare with, cell by cell (Table I: Avg., Med., Init., >1m, Ratio).
struct PaperCells {
  double avg_m = 0.0;
  double med_m = 0.0;
  double init = 0.0;
  double gt1m = 0.0;
  double ratio_pct = 0.0;
};
// The triggers of the paper's two methods (Table I's "Fixed" and "Our").
constexpr const char* kFixedWindowTrigger = "fixed_window";
constexpr const char* kPaperTrigger = "pdop_closest_point";

struct PaperRow {
  PaperCells fixed;  // kFixedWindowTrigger
  PaperCells gated;  // kPaperTrigger
  // The cells for a trigger, or nullptr if the paper has none for it.
  const PaperCells* For(const std::string& trigger) const {
    if (trigger == kFixedWindowTrigger) return &fixed;
    if (trigger == kPaperTrigger) return &gated;
    return nullptr;
  }
};

// One row of a Monte Carlo table: the base scenario and estimator with this row's overrides.
struct RowConfig {
  std::string name;
  sim::ScenarioOptions scenario;
  schema::EstimatorConfig estimator;
  std::optional<PaperRow> paper;
};

// The largest seed a config or the command line may give: 2^63-1 (the command line's limit; every
// seed up to it is written and read back exactly, in configs, manifests, shards and chunk stores).
constexpr std::uint64_t kMaxSeed = 9223372036854775807ull;

// One experiment (configs/*.yaml, read by the config layer): a scenario to simulate and the
// estimator to run on it, and for `run`, the rows of a Monte Carlo table. docs/config.md lists
// the keys with units.
struct ExperimentConfig {
  std::string name;  // the file's stem, e.g. "tunnel"
  std::uint64_t seed = 1;
  int realizations = 100;          // per row (run)
  int bootstrap_resamples = 1000;  // for the 95% intervals of summary.csv (run)
  sim::ScenarioOptions scenario;
  schema::EstimatorConfig estimator;
  std::vector<RowConfig> rows;         // empty: one row, the base
  std::vector<std::string> only_rows;  // run these rows only (names); empty: all
  // Sweep axes (anchorbench sweep): dotted key -> values ("0.5,1,2" or a range "0.25:3:0.25").
  std::vector<std::pair<std::string, std::string>> sweep;
  // The navigation study (anchorbench navigate; docs/navigation.md): absent unless the file has it.
  std::optional<NavigationConfig> navigation;
  // The closed-loop exploration study (anchorbench explore; docs/guidance.md): absent unless given.
  std::optional<ExplorationConfig> exploration;
  // The PDOP study (anchorbench pdop-study; docs/pdop_studies.md): absent unless given.
  std::optional<PdopStudyConfig> pdop_study;
};

// The rows `run` executes: config.rows (those in only_rows, if given), or the base as a single
// row named "base".
std::vector<RowConfig> RowsOf(const ExperimentConfig& config);

}  // namespace anchorbench::schema
