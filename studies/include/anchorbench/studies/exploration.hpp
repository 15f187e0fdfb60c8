#pragma once
// The closed-loop exploration study (anchorbench explore; docs/guidance.md): the robot flies or
// drives while it initializes, and where it goes next may depend on what the certificate says.
// Each (row, realization) draws its anchors and its pattern (the row's trajectory) once; every
// policy then runs on them with the same random streams per link (common random numbers):
// - pattern: the row's trajectory, back and forth, until every anchor is certified or the run's
//   time is up;
// - guided: the same, but every decision_period_s the robot asks guidance (estimator/guide.hpp)
//   for the candidates within reach, flies to the one that brings a waiting anchor's region within
//   D soonest, ranges there for dwell_s, and flies back to where it left the pattern.
// Ranges are drawn where the body actually is (sim::RangeDraws), so a detour's ranges are real.

#include <optional>
#include <string>
#include <vector>

#include "anchorbench/engine/commit.hpp"
#include "anchorbench/engine/record_journal.hpp"
#include "anchorbench/engine/run_control.hpp"
#include "anchorbench/engine/unit_records.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/schema/experiment.hpp"

namespace anchorbench::studies {

struct ExplorationRecord {
  int row = 0;
  int realization = 0;
  std::string policy;
  int anchors = 0;
  int certified = 0;           // anchors the trigger initialized within the run
  int beyond_accuracy = 0;     // of those, farther than D (the certificate's accuracy_m) from the truth
  double max_error_m = 0.0;    // the largest error among the certified (0: none)
  double t_all_certified_s = -1.0;  // when the last anchor was certified; -1: not all were
  double duration_s = 0.0;     // the run's end: every anchor certified, or max_duration_s
  double distance_m = 0.0;     // the body's path length until every anchor was certified (or the run's end)
  int detours = 0;             // places flown to off the pattern
  // With the config's navigation section: the navigation filter's position RMSE over the whole
  // run (max_duration_s for every policy) with the certified anchors from their certification; -1: none.
  double navigation_rmse_m = -1.0;
  std::vector<double> navigation_error_by_bin_m;  // its mean error per navigation.error_bin_s bin
};

// Refuses (InputError) a config without an `exploration` section, one CheckExperiment refuses, or
// a row whose ranging rate or environment the loop cannot run.
void CheckExploration(const schema::ExperimentConfig& config, const registry::Components& components);

// One (row, realization): every policy of the config on the same anchors, pattern and streams;
// with `navigation`, each run then navigated with its certified anchors (the odometry drawn from
// the stream (seed, realization, schema::kNavigationStream), the same for every policy).
std::vector<ExplorationRecord> ExploreRealization(const schema::RowConfig& row, int row_index, std::uint64_t seed,
                                                  int realization, const schema::ExplorationConfig& exploration,
                                                  const std::optional<schema::NavigationConfig>& navigation,
                                                  const registry::Components& components);

// Every row and realization on `threads` threads, ordered by row, realization, policy: the same
// for any thread count. Checks the config first (CheckExploration). With a journal, its units that
// read back are taken as they are, and each unit computed is appended to it as it finishes
// (unit_records.hpp): a killed run resumes with the same bytes.
// The study's units (unit = row * realizations + realization) for the runner (unit_records.hpp):
// computed by ExploreRealization, kept as exploration_lines.hpp's text. It holds what it needs of
// the config; `components` must outlive it.
engine::UnitRecords<ExplorationRecord> ExplorationUnits(const schema::ExperimentConfig& config,
                                                        const registry::Components& components);

std::vector<ExplorationRecord> RunExploration(const schema::ExperimentConfig& config,
                                              const registry::Components& components, int threads,
                                              const engine::RunControl& control = {}, engine::RecordJournal* journal = nullptr);

// exploration.csv (one line per run), exploration_summary.csv and exploration.md (per row and
// policy), with a navigation section navigation_error.csv (the navigation study's format, a policy
// for each method), manifest.json; returns the Markdown.
std::string WriteExplorationFiles(const engine::FileWriter& write, const schema::ExperimentConfig& config,
                                  const std::vector<ExplorationRecord>& records, const report::RunInfo& info);

}  // namespace anchorbench::studies
