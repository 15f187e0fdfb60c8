#include "anchorbench/studies/navigation.hpp"

#include <map>
#include <sstream>

#include "anchorbench/engine/executor.hpp"
#include "anchorbench/studies/navigation_lines.hpp"
#include "anchorbench/engine/unit_records.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/report/navigation_report.hpp"
#include "anchorbench/engine/monte_carlo.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/schema/random_streams.hpp"
#include "anchorbench/sim/scenario.hpp"

namespace anchorbench::studies {

using engine::CheckExperiment;
using engine::FileWriter;
using engine::ParallelRecords;
using engine::RecordJournal;
using engine::RunControl;
using engine::RunRealization;
using engine::RunUnitRecords;
using engine::Shard;
using engine::UnitRecords;

nav::NavigationOptions OptionsOf(const schema::NavigationConfig& c, double row_sigma_range_m) {
  nav::NavigationOptions o;
  o.drift = {c.sigma_bias_mps_per_sqrt_s, c.sigma_heading_rad_per_sqrt_s, c.sigma_step_m_per_sqrt_s};
  o.sigma_start_m = c.sigma_start_m;
  // Unset, the filter knows the row's range noise, as a robot's would know its radios'.
  o.sigma_range_m = c.sigma_range_m > 0.0 ? c.sigma_range_m : row_sigma_range_m;
  o.gate_chi2 = c.gate_chi2;
  o.fix_anchors = c.fix_anchors;
  o.kth_anchor = c.kth_anchor;
  o.error_bin_s = c.error_bin_s;
  return o;
}

std::vector<MethodAnchors> TriggerAnchors(const std::vector<schema::Attempt>& attempts,
                                          const std::vector<std::string>& triggers, schema::MirroredAnchorUse mirrored,
                                          double t_end_s) {
  std::vector<MethodAnchors> methods;
  for (const std::string& trigger : triggers) {
    std::vector<nav::UsableAnchor> anchors;
    for (const schema::Attempt& a : attempts) {
      if (a.method != trigger || !a.solve) continue;
      const bool mirror = !a.initialized && a.solve->status == estimator::SolveStatus::kHeightUnobservable;
      if (!(a.initialized || (mirror && mirrored != schema::MirroredAnchorUse::kSkip))) continue;
      // The fixed window at the end of the data; a refused online solve when it last ran.
      const std::optional<double> t_s = trigger == schema::kFixedWindowTrigger ? std::optional(t_end_s)
                                        : a.t_init_s                            ? a.t_init_s
                                                                                : a.t_failed_solve_s;
      if (!t_s) continue;
      anchors.push_back({a.anchor_id, *t_s, a.solve->p_world_anchor, a.solve->bias_m, a.solve->covariance,
                         mirror && mirrored == schema::MirroredAnchorUse::kHorizontal});
    }
    methods.push_back({trigger, std::move(anchors)});
  }
  return methods;
}

std::vector<NavigationRecord> NavigateMethods(const Trajectory& run, const std::vector<MethodAnchors>& methods,
                                              const nav::NavigationOptions& options, sim::RandomStream& rng, int row,
                                              int realization) {
  const std::vector<nav::OdometryStep> odometry = nav::SimulateOdometry(run.t_s, run.p_world_tag, options.drift, rng);
  Eigen::Vector3d p_start = run.p_world_tag.front();
  for (int i = 0; i < 3; ++i) p_start[i] += options.sigma_start_m * rng.Normal();
  std::vector<NavigationRecord> records;
  for (const auto& [method, anchors] : methods) {
    records.push_back(
        {row, realization, method, nav::Navigate(run.t_s, run.p_world_tag, odometry, p_start, run.ranges, anchors, options)});
  }
  return records;
}

std::vector<std::string> NavigationMethods(const schema::RowConfig& row) {
  std::vector<std::string> methods = row.estimator.triggers;
  methods.push_back(kTrueAnchors);
  methods.push_back(kNoAnchors);
  return methods;
}

std::vector<NavigationRecord> NavigateRealization(const schema::RowConfig& row, int row_index, std::uint64_t seed,
                                                  int realization, const schema::NavigationConfig& navigation,
                                                  const registry::Components& components) {
  const sim::Scenario scenario = sim::GenerateScenario(row.scenario, seed, static_cast<std::uint64_t>(realization));
  std::vector<estimator::RangeSample> samples;
  const std::vector<schema::Attempt> attempts =
      RunRealization(row, row_index, seed, realization, scenario, components, samples);
  Trajectory run{scenario.t_s, scenario.p_world_tag_true.front(), {}};  // tag 0
  for (const sim::SimRange& r : scenario.ranges) {
    if (r.tag_id == 0) run.ranges.push_back({r.epoch, r.anchor_id, r.range_m});
  }
  std::vector<MethodAnchors> methods = TriggerAnchors(attempts, row.estimator.triggers, navigation.height_unobservable,
                                                      scenario.t_s.empty() ? 0.0 : scenario.t_s.back());
  std::vector<nav::UsableAnchor> truth;
  for (const sim::SimAnchor& a : scenario.anchors) {
    truth.push_back({a.id, scenario.t_s.front(), a.p_world_anchor, a.bias_m, Eigen::Matrix4d::Zero()});
  }
  methods.push_back({kTrueAnchors, std::move(truth)});
  methods.push_back({kNoAnchors, {}});
  sim::RandomStream rng(seed, static_cast<std::uint64_t>(realization), schema::kNavigationStream);
  return NavigateMethods(run, methods, OptionsOf(navigation, row.scenario.ranging.sigma_range_m), rng, row_index,
                         realization);
}

void CheckNavigation(const schema::ExperimentConfig& config, const registry::Components& components) {
  if (!config.navigation) {
    throw schema::InputError(config.name + ": no 'navigation' section: nothing says how the robot drifts "
                                           "(docs/navigation.md)");
  }
  CheckExperiment(config, components);
  for (const schema::RowConfig& row : schema::RowsOf(config)) {
    const sim::ScenarioOptions& scenario = row.scenario;
    CheckErrorBins(scenario.MaxEpochs() / scenario.trajectory.rate_hz, *config.navigation, config.name + ": row '" + row.name + "'");
  }
}

void CheckErrorBins(double duration_s, const schema::NavigationConfig& navigation, const std::string& what) {
  const double bins = duration_s / navigation.error_bin_s;
  if (!(bins <= kMaxErrorBins)) {
    throw schema::InputError(what + ": key 'navigation.error_bin_s': " + io::FormatNumber(navigation.error_bin_s) +
                             " s bins over a run of up to " + io::FormatNumber(duration_s) + " s are " +
                             io::FormatNumber(std::ceil(bins)) + " bins; at most 1e5: use wider bins");
  }
}

UnitRecords<NavigationRecord> NavigationUnits(const schema::ExperimentConfig& config,
                                              const registry::Components& components) {
  const std::vector<schema::RowConfig> rows = schema::RowsOf(config);
  const int realizations = config.realizations;
  UnitRecords<NavigationRecord> study;
  study.units = static_cast<int>(rows.size()) * realizations;
  study.compute = [rows, realizations, seed = config.seed, navigation = *config.navigation, &components](int unit) {
    const int row = unit / realizations;
    return NavigateRealization(rows[static_cast<std::size_t>(row)], row, seed, unit % realizations, navigation,
                               components);
  };
  study.text = NavigationUnitText;
  study.read = [rows, realizations](const std::string& text, const engine::UnitPlace& place, int unit) {
    const int row = unit / realizations;
    return ReadNavigationUnit(text, place, row, unit % realizations,
                              NavigationMethods(rows[static_cast<std::size_t>(row)]));
  };
  return study;
}

std::vector<NavigationRecord> RunNavigation(const schema::ExperimentConfig& config,
                                            const registry::Components& components, int threads, const Shard& shard,
                                            const RunControl& control, RecordJournal* journal) {
  CheckNavigation(config, components);
  return RunUnitRecords(NavigationUnits(config, components), threads, shard, control, journal);
}

std::vector<NavigationRecord> NavigateUnits(int units, int threads,
                                            const std::function<std::vector<NavigationRecord>(int unit)>& unit,
                                            const RunControl& control) {
  return ParallelRecords(units, threads, unit, control);
}

std::string WriteNavigationTables(const FileWriter& write, const schema::ExperimentConfig& config,
                                  const std::vector<schema::RowConfig>& rows,
                                  const std::vector<NavigationRecord>& records) {
  const std::vector<report::NavigationSummary> summaries = report::SummarizeNavigation(
      records, static_cast<int>(rows.size()), config.bootstrap_resamples, config.seed, kNoAnchors);
  write("navigation.csv", [&](std::ostream& file) { report::WriteNavigationCsv(file, records, rows); });
  write("navigation_summary.csv", [&](std::ostream& file) { report::WriteNavigationSummaryCsv(file, summaries, rows); });
  write("navigation_error.csv", [&](std::ostream& file) {
    report::WriteNavigationErrorCsv(file, records, rows, config.navigation->error_bin_s);
  });
  std::ostringstream markdown;
  report::WriteNavigationMarkdown(markdown, summaries, rows, config);
  write("navigation.md", [&](std::ostream& file) { file << markdown.str(); });
  return markdown.str();
}

std::string WriteNavigationFiles(const FileWriter& write, const schema::ExperimentConfig& config,
                                 const std::vector<NavigationRecord>& records, const report::RunInfo& info) {
  const std::string markdown = WriteNavigationTables(write, config, schema::RowsOf(config), records);
  write("manifest.json", [&](std::ostream& file) { file << report::ManifestJson(config, info); });
  return markdown;
}

}  // namespace anchorbench::studies
