#pragma once
// The navigation study (anchorbench navigate; docs/navigation.md): for each (row, realization),
// the Monte Carlo's triggers initialize the anchors, and the navigation filter (nav/) runs the
// robot's drifting odometry with each trigger's anchors from the moment they were initialized,
// beside two baselines: the true anchors from the start (the floor) and none (the drift). Every
// method of a realization sees the same trajectory, ranges and odometry.

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "anchorbench/engine/commit.hpp"
#include "anchorbench/engine/record_journal.hpp"
#include "anchorbench/engine/run_control.hpp"
#include "anchorbench/engine/unit_records.hpp"
#include "anchorbench/engine/shard.hpp"
#include "anchorbench/nav/navigate.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/schema/experiment.hpp"
#include "anchorbench/sim/random_stream.hpp"

namespace anchorbench::studies {

inline constexpr const char* kTrueAnchors = "true_anchors";  // baseline: the truth from t = 0
inline constexpr const char* kNoAnchors = "no_anchors";      // baseline: odometry alone

using nav::NavigationRecord;

// One tag's run as the filter sees it: the true positions per epoch and the ranges in epoch order.
struct Trajectory {
  std::vector<double> t_s;
  std::vector<Eigen::Vector3d> p_world_tag;
  std::vector<nav::RangeAt> ranges;
};
// A method's name and the anchors it hands the filter.
using MethodAnchors = std::pair<std::string, std::vector<nav::UsableAnchor>>;

// The filter's options from the config's section; `sigma_range_m` 0 there takes `row_sigma_range_m`.
nav::NavigationOptions OptionsOf(const schema::NavigationConfig& navigation, double row_sigma_range_m);

// Each trigger's anchors, in `triggers`' order: those it initialized (and, as `mirrored` says,
// those it refused as height_unobservable), usable from their initialization's time; the fixed
// window's from `t_end_s`, the end of the data, when its one solve can run (its t_init is the time
// of the last sample it used, which a live robot cannot know is the last).
std::vector<MethodAnchors> TriggerAnchors(const std::vector<schema::Attempt>& attempts,
                                          const std::vector<std::string>& triggers, schema::MirroredAnchorUse mirrored,
                                          double t_end_s);

// One realization: the odometry and the start drawn from `rng`, then every method on them (common
// random numbers), one record each.
std::vector<NavigationRecord> NavigateMethods(const Trajectory& run, const std::vector<MethodAnchors>& methods,
                                              const nav::NavigationOptions& options, sim::RandomStream& rng, int row,
                                              int realization);

// The methods of a row: its triggers, then the two baselines.
std::vector<std::string> NavigationMethods(const schema::RowConfig& row);

// One unit: the row's triggers, then the baselines, on tag 0's trajectory. The odometry draws from
// the stream (seed, realization, schema::kNavigationStream).
std::vector<NavigationRecord> NavigateRealization(const schema::RowConfig& row, int row_index, std::uint64_t seed,
                                                  int realization, const schema::NavigationConfig& navigation,
                                                  const registry::Components& components);

// Refuses (InputError) a config without a `navigation` section, one CheckExperiment refuses, or
// one whose runs would hold too many error bins (CheckErrorBins).
void CheckNavigation(const schema::ExperimentConfig& config, const registry::Components& components);

// At most kMaxErrorBins bins of navigation.error_bin_s in a run of `duration_s` (each run keeps
// one error per bin and method): refused before any work (InputError naming `what`).
inline constexpr double kMaxErrorBins = 1e5;
void CheckErrorBins(double duration_s, const schema::NavigationConfig& navigation, const std::string& what);

// Every row and realization (or the units `shard` holds: unit = row * realizations +
// realization, as navigation_shard.hpp's) on `threads` threads, ordered by row, realization,
// method: the same for any thread count. Checks the config first (CheckNavigation). With a
// journal, its units that read back are taken as they are (the rest of its blocks refused in it),
// and each unit computed is appended to it as it finishes: a killed run resumes with the same bytes.
// The study's units (unit = row * realizations + realization) for the runner (unit_records.hpp):
// computed by NavigateRealization, kept as navigation_lines.hpp's text. It holds what it needs of
// the config; `components` must outlive it.
engine::UnitRecords<NavigationRecord> NavigationUnits(const schema::ExperimentConfig& config,
                                                      const registry::Components& components);

std::vector<NavigationRecord> RunNavigation(const schema::ExperimentConfig& config,
                                            const registry::Components& components, int threads,
                                            const engine::Shard& shard = {}, const engine::RunControl& control = {},
                                            engine::RecordJournal* journal = nullptr);

// `units` units on `threads` threads (ParallelFor), their records joined in unit order: the same
// for any thread count. `control` sees every unit done, and may stop the rest.
std::vector<NavigationRecord> NavigateUnits(int units, int threads,
                                            const std::function<std::vector<NavigationRecord>(int unit)>& unit,
                                            const engine::RunControl& control = {});

// navigation.csv, navigation_summary.csv, navigation_error.csv and navigation.md of `records`
// (whose row indexes `rows`) through `write`; returns navigation.md's text.
std::string WriteNavigationTables(const engine::FileWriter& write, const schema::ExperimentConfig& config,
                                  const std::vector<schema::RowConfig>& rows,
                                  const std::vector<NavigationRecord>& records);

// The tables of the config's rows and manifest.json; returns navigation.md's text.
std::string WriteNavigationFiles(const engine::FileWriter& write, const schema::ExperimentConfig& config,
                                 const std::vector<NavigationRecord>& records, const report::RunInfo& info);

}  // namespace anchorbench::studies
