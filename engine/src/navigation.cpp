#include "anchorbench/engine/navigation.hpp"

#include <sstream>

#include "anchorbench/engine/executor.hpp"
#include "anchorbench/report/navigation_report.hpp"
#include "anchorbench/engine/monte_carlo.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/schema/random_streams.hpp"
#include "anchorbench/sim/scenario.hpp"

namespace anchorbench::engine {
namespace {

nav::NavigationOptions OptionsOf(const schema::NavigationConfig& c, const schema::RowConfig& row) {
  nav::NavigationOptions o;
  o.drift = {c.sigma_bias_mps_per_sqrt_s, c.sigma_heading_rad_per_sqrt_s, c.sigma_step_m_per_sqrt_s};
  o.sigma_start_m = c.sigma_start_m;
  // Unset, the filter knows the row's range noise, as a robot's would know its radios'.
  o.sigma_range_m = c.sigma_range_m > 0.0 ? c.sigma_range_m : row.scenario.ranging.sigma_range_m;
  o.gate_chi2 = c.gate_chi2;
  o.fix_anchors = c.fix_anchors;
  o.kth_anchor = c.kth_anchor;
  o.error_bin_s = c.error_bin_s;
  return o;
}

// A trigger's anchors as the filter may use them: those it initialized with an estimate (and, as
// `mirrored` says, those it refused as height_unobservable), from the time it did.
std::vector<nav::UsableAnchor> AnchorsOf(const std::vector<schema::Attempt>& attempts, const std::string& method,
                                         schema::MirroredAnchorUse mirrored) {
  std::vector<nav::UsableAnchor> anchors;
  for (const schema::Attempt& a : attempts) {
    if (a.method != method || !a.solve || !a.t_init_s) continue;
    const bool mirror = !a.initialized && a.solve->status == estimator::SolveStatus::kHeightUnobservable;
    if (!(a.initialized || (mirror && mirrored != schema::MirroredAnchorUse::kSkip))) continue;
    anchors.push_back({a.anchor_id, *a.t_init_s, a.solve->p_world_anchor, a.solve->bias_m, a.solve->covariance,
                       mirror && mirrored == schema::MirroredAnchorUse::kHorizontal});
  }
  return anchors;
}

}  // namespace

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
  const std::vector<Eigen::Vector3d>& truth = scenario.p_world_tag_true.front();  // tag 0
  const nav::NavigationOptions options = OptionsOf(navigation, row);
  sim::RandomStream rng(seed, static_cast<std::uint64_t>(realization), schema::kNavigationStream);
  const std::vector<nav::OdometryStep> odometry = nav::SimulateOdometry(scenario.t_s, truth, options.drift, rng);
  Eigen::Vector3d p_start = truth.front();
  for (int i = 0; i < 3; ++i) p_start[i] += options.sigma_start_m * rng.Normal();
  std::vector<nav::RangeAt> ranges;
  for (const sim::SimRange& r : scenario.ranges) {
    if (r.tag_id == 0) ranges.push_back({r.epoch, r.anchor_id, r.range_m});
  }
  std::vector<NavigationRecord> records;
  for (const std::string& method : NavigationMethods(row)) {
    std::vector<nav::UsableAnchor> anchors;
    if (method == kTrueAnchors) {
      for (const sim::SimAnchor& a : scenario.anchors) {
        anchors.push_back({a.id, scenario.t_s.front(), a.p_world_anchor, a.bias_m, Eigen::Matrix4d::Zero()});
      }
    } else if (method != kNoAnchors) {
      anchors = AnchorsOf(attempts, method, navigation.height_unobservable);
    }
    records.push_back({row_index, realization, method,
                       nav::Navigate(scenario.t_s, truth, odometry, p_start, ranges, std::move(anchors), options)});
  }
  return records;
}

void CheckNavigation(const schema::ExperimentConfig& config, const registry::Components& components) {
  if (!config.navigation) {
    throw schema::InputError(config.name + ": no 'navigation' section: nothing says how the robot drifts "
                                           "(docs/navigation.md)");
  }
  CheckExperiment(config, components);
}

std::vector<NavigationRecord> RunNavigation(const schema::ExperimentConfig& config,
                                            const registry::Components& components, int threads) {
  CheckNavigation(config, components);
  const std::vector<schema::RowConfig> rows = schema::RowsOf(config);
  const int units = static_cast<int>(rows.size()) * config.realizations;
  std::vector<std::vector<NavigationRecord>> by_unit(static_cast<std::size_t>(units));
  ParallelFor(units, threads, [&](int unit, int) {
    const int row = unit / config.realizations;
    by_unit[static_cast<std::size_t>(unit)] = NavigateRealization(
        rows[static_cast<std::size_t>(row)], row, config.seed, unit % config.realizations, *config.navigation, components);
  });
  std::vector<NavigationRecord> records;
  for (std::vector<NavigationRecord>& unit : by_unit) {
    for (NavigationRecord& r : unit) records.push_back(std::move(r));
  }
  return records;
}

std::string WriteNavigationFiles(const FileWriter& write, const schema::ExperimentConfig& config,
                                 const std::vector<NavigationRecord>& records, const report::RunInfo& info) {
  const std::vector<schema::RowConfig> rows = schema::RowsOf(config);
  const std::vector<report::NavigationSummary> summaries =
      report::SummarizeNavigation(records, static_cast<int>(rows.size()), config.bootstrap_resamples, config.seed);
  write("navigation.csv", [&](std::ostream& file) { report::WriteNavigationCsv(file, records, rows); });
  write("navigation_summary.csv", [&](std::ostream& file) { report::WriteNavigationSummaryCsv(file, summaries, rows); });
  write("navigation_error.csv", [&](std::ostream& file) {
    report::WriteNavigationErrorCsv(file, records, rows, config.navigation->error_bin_s);
  });
  std::ostringstream markdown;
  report::WriteNavigationMarkdown(markdown, summaries, rows, config);
  write("navigation.md", [&](std::ostream& file) { file << markdown.str(); });
  write("manifest.json", [&](std::ostream& file) { file << report::ManifestJson(config, info); });
  return markdown.str();
}

}  // namespace anchorbench::engine
