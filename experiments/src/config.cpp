#include "anchorbench/experiments/config.hpp"

#include <algorithm>
#include <filesystem>
#include <limits>

#include "anchorbench/experiments/anchor_bank.hpp"
#include "anchorbench/experiments/config_yaml.hpp"
#include "anchorbench/experiments/input_error.hpp"
#include "anchorbench/experiments/yaml_section.hpp"

namespace anchorbench::experiments {
namespace {

constexpr Bounds kAny{};
constexpr Bounds kNonNegative{0.0};
constexpr Bounds kPositive{0.0, 1e300, true};
constexpr Bounds kProbability{0.0, 1.0};

// One visitor per options struct lists its keys once; YamlSection reads them, YamlWriter writes them.

// The keys tunnels and halls share: a box and its anchors.
template <typename V, typename Box>
void VisitBox(V& v, Box& o) {
  v.Number("length_m", o.length_m, kPositive);
  v.Number("width_m", o.width_m, kPositive);
  v.Number("height_m", o.height_m, kPositive);
  v.Integer("num_anchors", o.num_anchors, 1, 10000);
  v.Number("anchor_height_min_m", o.anchor_height_min_m, kNonNegative);
  v.Number("anchor_height_max_m", o.anchor_height_max_m, kNonNegative);
}

template <typename V>
void VisitTunnel(V& v, sim::TunnelOptions& o) {
  VisitBox(v, o);
  v.Number("along_jitter_m", o.along_jitter_m, kNonNegative);
  v.Check(o);
}

template <typename V>
void VisitHall(V& v, sim::HallOptions& o) {
  VisitBox(v, o);
  v.Choice("anchor_walls", o.anchor_walls, sim::ParseHallWalls, [](auto w) { return sim::ToString(w); }, "all, front");
  v.Check(o);
}

template <typename V>
void VisitTrajectory(V& v, sim::TrajectoryOptions& o) {
  v.Choice("kind", o.kind, sim::ParseTrajectoryKind, [](auto k) { return sim::ToString(k); },
           "random, straight, planar, short");
  v.Number("fraction_straight", o.fraction_straight, kProbability);
  v.Number("fraction_planar", o.fraction_planar, kProbability);
  v.Number("fraction_short", o.fraction_short, kProbability);
  v.Number("rate_hz", o.rate_hz, {0.0, 1000.0, true});
  v.Number("speed_mps", o.speed_mps, kPositive);
  v.Number("speed_variation", o.speed_variation, {0.0, 0.99});
  v.Number("height_m", o.height_m, kNonNegative);
  v.Number("lateral_excursion_m", o.lateral_excursion_m, kNonNegative);
  v.Number("vertical_excursion_m", o.vertical_excursion_m, kNonNegative);
  v.Number("planar_vertical_excursion_m", o.planar_vertical_excursion_m, kNonNegative);
  v.Number("min_period_s", o.min_period_s, kPositive);
  v.Number("max_period_s", o.max_period_s, kPositive);
  v.Number("short_fraction", o.short_fraction, {0.0, 1.0, true});
  v.Number("hall_duration_s", o.hall_duration_s, kPositive);
  v.Check(o);
}

template <typename V>
void VisitRanging(V& v, sim::RangeModelOptions& o) {
  v.Number("sigma_range_m", o.sigma_range_m, kNonNegative);
  v.Choice("bias_distribution", o.bias_distribution, sim::ParseBiasDistribution,
           [](auto d) { return sim::ToString(d); }, "uniform, normal");
  v.Number("bias_a_m", o.bias_a_m, kAny);
  v.Number("bias_b_m", o.bias_b_m, kAny);
  v.Number("outlier_probability", o.outlier_probability, kProbability);
  v.Number("outlier_burst_length", o.outlier_burst_length, {1.0});
  v.Choice("outlier_kind", o.outlier_kind, sim::ParseOutlierKind, [](auto k) { return sim::ToString(k); },
           "positive, symmetric");
  v.Number("outlier_min_m", o.outlier_min_m, kNonNegative);
  v.Number("outlier_max_m", o.outlier_max_m, kNonNegative);
  v.Number("max_range_m", o.max_range_m, kPositive);
  v.Number("dropout_probability", o.dropout_probability, {0.0, 0.99});
  v.Number("sigma_position_m", o.sigma_position_m, kNonNegative);
  v.Check(o);
}

template <typename V>
void VisitScenario(V& v, sim::ScenarioOptions& o) {
  v.Choice("environment", o.environment, sim::ParseEnvironmentKind, [](auto k) { return sim::ToString(k); },
           "tunnel, hall");
  v.VectorList("tag_offsets_m", o.tag_offsets_m);
  v.Section("tunnel", [&](auto& s) { VisitTunnel(s, o.tunnel); });
  v.Section("hall", [&](auto& s) { VisitHall(s, o.hall); });
  v.Section("trajectory", [&](auto& s) { VisitTrajectory(s, o.trajectory); });
  v.Section("ranging", [&](auto& s) { VisitRanging(s, o.ranging); });
  v.Check(o);
}

// Names a registry knows (the built-ins; a program with parts of its own validates against its
// registries when it builds them).
template <typename Registry>
auto NameIn(const Registry& registry) {
  return [&registry](std::string_view name, std::string* value) {
    if (!registry.Knows(std::string(name))) return false;
    *value = name;
    return true;
  };
}

std::string Same(const std::string& name) { return name; }

template <typename V>
void VisitEstimator(V& v, estimator::InitializerOptions& o) {
  const estimator::Components& parts = BuiltinComponents();
  v.Choice("solver", o.solver_name, NameIn(parts.solvers), Same,
           "anchorbench list shows them: ls_single, ls_double, lm_l2, lm_huber, lm_cauchy, lm_adaptive, nlopt:<ALGORITHM>");
  v.ChoiceList("triggers", o.triggers, [&](const std::string& name) { return parts.triggers.Knows(name); },
               "anchorbench list shows them: pdop_closest_point, pdop_ls, pdop_nls, pdop_true, fixed_window, "
               "sample_count, timeout");
  v.Section("filter", [&](auto& s) {
    s.Choice("kind", o.filter.kind, NameIn(parts.filters), Same, "none, consistency, ransac");
    s.Number("tau_m", o.filter.consistency.tau_m, kNonNegative);
    s.Integer("reseed_after_rejections", o.filter.consistency.reseed_after_rejections, 0, 1000000);
    s.Section("ransac", [&](auto& r) {
      estimator::RansacOptions& ransac = o.filter.ransac;
      r.Number("success_probability", ransac.success_probability, {0.0, 1.0, true});
      r.Integer("subset_size", ransac.subset_size, 6, 100000);
      r.Number("outlier_fraction", ransac.outlier_fraction, {0.0, 0.99});
      r.Number("inlier_threshold_m", ransac.inlier_threshold_m, kPositive);
      r.Check(ransac);
    });
  });
  v.Section("trigger", [&](auto& s) {
    s.Number("pdop_threshold", o.trigger.pdop_threshold, kPositive);
    s.Integer("min_samples", o.min_samples, 6, 100000000);
    s.Number("retry_growth", o.retry_growth, {1.0, 1e300, true});
    s.Integer("sample_count", o.trigger.sample_count, 1, 100000000);
    s.Number("timeout_s", o.trigger.timeout_s, kNonNegative);
    s.Integer("evaluate_every", o.trigger.evaluate_every, 1, 100000000);
  });
  v.Section("ls", [&](auto& s) {
    estimator::LsOptions& ls = o.solver.ls;
    s.Choice("pivot", ls.pivot, estimator::ParseLsPivot, [](auto p) { return estimator::ToString(p); },
             "shortest_range, minimum_variance");
    s.Number("sigma_range_m", ls.sigma_range_m, kPositive);
    s.Number("sigma_position_m", ls.sigma_position_m, kNonNegative);
  });
  v.Section("nls", [&](auto& s) {
    estimator::NlsOptions& n = o.solver.nls;
    s.Choice("kernel", n.kernel, estimator::ParseKernelMode, [](auto k) { return estimator::ToString(k); },
             "adaptive, l2, fixed");
    s.Number("fixed_alpha", n.fixed_alpha, {-1000.0, 2.0});
    s.Number("alpha_min", n.alpha_min, {-1000.0, 2.0});
    s.Number("kernel_scale_m", n.kernel_scale_m, kPositive);
    s.Number("truncation", n.truncation, kPositive);
    s.Integer("max_iterations", n.max_iterations, 1, 100000);
    s.Number("step_tolerance_m", n.step_tolerance_m, kPositive);
    s.Number("alpha_tolerance", n.alpha_tolerance, kPositive);
    s.Number("initial_damping", n.initial_damping, kNonNegative);
    s.Flag("l2_warm_start", n.l2_warm_start);
    s.Check(n);
  });
  v.Check(o);
}

template <typename V>
void VisitPaperCells(V& v, PaperCells& cells) {
  v.Number("avg_m", cells.avg_m, kNonNegative);
  v.Number("med_m", cells.med_m, kNonNegative);
  v.Number("init", cells.init, kNonNegative);
  v.Number("gt1m", cells.gt1m, kNonNegative);
  v.Number("ratio_pct", cells.ratio_pct, {0.0, 100.0});
}

template <typename V>
void VisitRow(V& v, RowConfig& row) {
  v.Text("name", row.name);
  v.Section("scenario", [&](auto& s) { VisitScenario(s, row.scenario); });
  v.Section("estimator", [&](auto& s) { VisitEstimator(s, row.estimator); });
  v.OptionalSection("paper", row.paper, [](auto& s, PaperRow& paper) {
    s.Section("fixed", [&](auto& cells) { VisitPaperCells(cells, paper.fixed); });
    s.Section("gated", [&](auto& cells) { VisitPaperCells(cells, paper.gated); });
  });
}

template <typename V>
void VisitExperiment(V& v, ExperimentConfig& c) {
  int seed = static_cast<int>(c.seed);
  v.Integer("seed", seed, 0, std::numeric_limits<int>::max());
  c.seed = static_cast<std::uint64_t>(seed);
  v.Integer("realizations", c.realizations, 1, 100000000);
  v.Integer("bootstrap_resamples", c.bootstrap_resamples, 0, 1000000);
  v.Section("scenario", [&](auto& s) { VisitScenario(s, c.scenario); });
  v.Section("estimator", [&](auto& s) { VisitEstimator(s, c.estimator); });
  v.TextList("only_rows", c.only_rows);
  v.TextMap("sweep", c.sweep);
  // Rows start from the base read above, so the base must come first in the visit.
  int index = 0;
  v.List("rows", c.rows,
         [&] { return RowConfig{std::to_string(++index), c.scenario, c.estimator, std::nullopt}; },
         [](auto& s, RowConfig& row) { VisitRow(s, row); });
}

}  // namespace

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

ExperimentConfig LoadConfig(const std::string& path, const std::vector<std::string>& overrides) {
  YAML::Node root = LoadConfigYaml(path, overrides);
  ExperimentConfig config;
  config.name = std::filesystem::path(path).stem().string();
  YamlSection top(root, "", path);
  VisitExperiment(top, config);
  top.Finish();
  for (const std::string& name : config.only_rows) {
    const bool known = std::any_of(config.rows.begin(), config.rows.end(), [&](const RowConfig& r) { return r.name == name; });
    if (!known) top.Fail("only_rows", "no row named '" + name + "'");
  }
  return config;
}

std::string ToYaml(const ExperimentConfig& config) {
  ExperimentConfig copy = config;
  YAML::Node root(YAML::NodeType::Map);
  YamlWriter writer(root);
  VisitExperiment(writer, copy);
  YAML::Emitter out;
  out << root;
  return out.c_str();
}

}  // namespace anchorbench::experiments
