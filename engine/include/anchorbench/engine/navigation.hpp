#pragma once
// The navigation study (anchorbench navigate; docs/navigation.md): for each (row, realization),
// the Monte Carlo's triggers initialize the anchors, and the navigation filter (nav/) runs the
// robot's drifting odometry with each trigger's anchors from the moment they were initialized,
// beside two baselines: the true anchors from the start (the floor) and none (the drift). Every
// method of a realization sees the same trajectory, ranges and odometry.

#include <string>
#include <vector>

#include "anchorbench/engine/commit.hpp"
#include "anchorbench/nav/navigate.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/schema/experiment.hpp"

namespace anchorbench::engine {

inline constexpr const char* kTrueAnchors = "true_anchors";  // baseline: the truth from t = 0
inline constexpr const char* kNoAnchors = "no_anchors";      // baseline: odometry alone

using nav::NavigationRecord;

// The methods of a row: its triggers, then the two baselines.
std::vector<std::string> NavigationMethods(const schema::RowConfig& row);

// One unit: the row's triggers, then the baselines, on tag 0's trajectory. The odometry draws from
// the stream (seed, realization, schema::kNavigationStream).
std::vector<NavigationRecord> NavigateRealization(const schema::RowConfig& row, int row_index, std::uint64_t seed,
                                                  int realization, const schema::NavigationConfig& navigation,
                                                  const registry::Components& components);

// Refuses (InputError) a config without a `navigation` section, or one CheckExperiment refuses.
void CheckNavigation(const schema::ExperimentConfig& config, const registry::Components& components);

// Every row and realization on `threads` threads, ordered by row, realization, method: the same
// for any thread count. Checks the config first (CheckNavigation).
std::vector<NavigationRecord> RunNavigation(const schema::ExperimentConfig& config,
                                            const registry::Components& components, int threads);

// navigation.csv, navigation_summary.csv, navigation_error.csv, navigation.md and manifest.json
// through `write`; returns navigation.md's text.
std::string WriteNavigationFiles(const FileWriter& write, const schema::ExperimentConfig& config,
                                 const std::vector<NavigationRecord>& records, const report::RunInfo& info);

}  // namespace anchorbench::engine
