#pragma once
// The experiment schema, listed once: one visitor per options struct names its keys. YamlSection
// reads a file through them (validating each struct with its own IsValid) and YamlWriter writes
// the resolved configuration back through the same visitors. Bounds appear here only for the
// experiment's own keys; the options structs check their limits themselves.

#include <limits>
#include <string>

#include "anchorbench/registry/components.hpp"
#include "anchorbench/schema/experiment.hpp"

namespace anchorbench::config::visit {

template <typename V, typename Options>
void Box(V& v, Options& o) {
  v.Number("length_m", o.length_m);
  v.Number("width_m", o.width_m);
  v.Number("height_m", o.height_m);
  v.Integer("num_anchors", o.num_anchors);
  v.Number("anchor_height_min_m", o.anchor_height_min_m);
  v.Number("anchor_height_max_m", o.anchor_height_max_m);
}

template <typename V>
void Tunnel(V& v, sim::TunnelOptions& o) {
  Box(v, o);
  v.Number("along_jitter_m", o.along_jitter_m);
  v.Check(o);
}

template <typename V>
void Hall(V& v, sim::HallOptions& o) {
  Box(v, o);
  v.Choice("anchor_walls", o.anchor_walls, sim::kHallWallsNames);
  v.Check(o);
}

template <typename V>
void Trajectory(V& v, sim::TrajectoryOptions& o) {
  v.Choice("kind", o.kind, sim::kTrajectoryKindNames);
  v.Number("fraction_straight", o.fraction_straight);
  v.Number("fraction_planar", o.fraction_planar);
  v.Number("fraction_short", o.fraction_short);
  v.Number("rate_hz", o.rate_hz);
  v.Number("speed_mps", o.speed_mps);
  v.Number("speed_variation", o.speed_variation);
  v.Number("height_m", o.height_m);
  v.Number("lateral_excursion_m", o.lateral_excursion_m);
  v.Number("vertical_excursion_m", o.vertical_excursion_m);
  v.Number("planar_vertical_excursion_m", o.planar_vertical_excursion_m);
  v.Number("min_period_s", o.min_period_s);
  v.Number("max_period_s", o.max_period_s);
  v.Number("short_fraction", o.short_fraction);
  v.Number("hall_duration_s", o.hall_duration_s);
  v.Number("approach_start_m", o.approach_start_m);
  v.Number("approach_end_m", o.approach_end_m);
  v.Number("approach_cone_deg", o.approach_cone_deg);
  v.Number("approach_duration_s", o.approach_duration_s);
  v.Check(o);
}

template <typename V>
void Ranging(V& v, sim::RangeModelOptions& o) {
  v.Number("sigma_range_m", o.sigma_range_m);
  v.Choice("bias_distribution", o.bias_distribution, sim::kBiasDistributionNames);
  v.Number("bias_a_m", o.bias_a_m);
  v.Number("bias_b_m", o.bias_b_m);
  v.Number("outlier_probability", o.outlier_probability);
  v.Number("outlier_burst_length", o.outlier_burst_length);
  v.Choice("outlier_kind", o.outlier_kind, sim::kOutlierKindNames);
  v.Number("outlier_min_m", o.outlier_min_m);
  v.Number("outlier_max_m", o.outlier_max_m);
  v.Number("max_range_m", o.max_range_m);
  v.Number("dropout_probability", o.dropout_probability);
  v.Number("sigma_position_m", o.sigma_position_m);
  v.Number("antenna_bias_m", o.antenna_bias_m);
  v.Number("tag_antenna_bias_m", o.tag_antenna_bias_m);
  v.Number("link_offset_m", o.link_offset_m);
  v.Number("range_scale_sigma", o.range_scale_sigma);
  v.Check(o);
}

// `environment`: the tunnel, the hall, or an environment of the caller's registry, its options
// in the section scenario.<name>.
template <typename V>
void EnvironmentName(V& v, sim::ScenarioOptions& o, const registry::Components& components) {
  std::string name = o.EnvironmentName();
  v.Name("environment", name, [&](const std::string& n, std::string* why) {
    sim::EnvironmentKind kind;
    if (sim::ParseEnvironmentKind(n, &kind) || components.environments.Knows(n, nullptr)) return true;
    if (why) *why = "unknown environment '" + n + "' (choices: " + sim::kEnvironmentKindNames.Choices() + ", or one registered)";
    return false;
  });
  v.Derive("environment", [&](std::string*) {
    o.custom_environment = sim::ParseEnvironmentKind(name, &o.environment) ? "" : name;
    return true;
  });
}

// After the scenario's own keys (a registered environment may not take one's name): the caller's
// environment's section, and the environment its registry builds from it.
template <typename V>
void CustomEnvironment(V& v, sim::ScenarioOptions& o, const registry::Components& components) {
  v.PartOptions(o.environment_options, {o.custom_environment}, components.environments.PartsWithOptions());
  v.Derive("environment", [&](std::string* why) {
    o.custom.reset();
    if (o.custom_environment.empty()) return true;
    o.custom = components.environments.Create(o.custom_environment, {}, why,
                                              registry::ValuesOf(o.environment_options, o.custom_environment));
    return o.custom != nullptr;
  });
}

template <typename V>
void Scenario(V& v, sim::ScenarioOptions& o, const registry::Components& components) {
  EnvironmentName(v, o, components);
  v.VectorList("tag_offsets_m", o.tag_offsets_m);
  v.Section("tunnel", [&](auto& s) { Tunnel(s, o.tunnel); });
  v.Section("hall", [&](auto& s) { Hall(s, o.hall); });
  v.Section("trajectory", [&](auto& s) { Trajectory(s, o.trajectory); });
  v.Section("ranging", [&](auto& s) { Ranging(s, o.ranging); });
  CustomEnvironment(v, o, components);
  v.Check(o);
}

template <typename V>
void Filter(V& v, schema::FilterConfig& o, const registry::Components& components) {
  v.Name("kind", o.kind, [&](const std::string& name, std::string* why) { return components.filters.Knows(name, why); });
  v.Number("tau_m", o.consistency.tau_m);
  v.Integer("reseed_after_rejections", o.consistency.reseed_after_rejections);
  v.Check(o.consistency);
  v.Section("ransac", [&](auto& r) {
    r.Choice("scheme", o.ransac.scheme, estimator::kRansacSchemeNames);
    r.Number("success_probability", o.ransac.success_probability);
    r.Integer("subset_size", o.ransac.subset_size);
    r.Number("outlier_fraction", o.ransac.outlier_fraction);
    r.Number("inlier_threshold_m", o.ransac.inlier_threshold_m);
    r.Integer("min_subsets", o.ransac.min_subsets);
    r.Integer("max_subsets", o.ransac.max_subsets);
    r.Check(o.ransac);
  });
}

// The initializer's keys, once under `trigger`: refused with their new place.
constexpr const char* kInitializerKeys[] = {"min_samples", "retry_growth", "max_buffered_samples", "at_cap"};

// `trigger`: what the built-in triggers are built from (schema::TriggerConfig).
template <typename V>
void Trigger(V& v, schema::TriggerConfig& o) {
  v.Number("pdop_threshold", o.pdop_threshold);
  v.Integer("sample_count", o.sample_count);
  v.Number("timeout_s", o.timeout_s);
  v.Integer("evaluate_every", o.evaluate_every);
  v.Number("evaluate_growth", o.evaluate_growth);
  v.Number("bias_aware_threshold", o.bias_aware_threshold);
  v.Number("confidence_threshold", o.confidence_threshold);
  v.Number("confidence_sigmas", o.confidence_sigmas);
  v.Number("horizontal_threshold", o.horizontal_threshold);
  for (const char* key : kInitializerKeys) v.Moved(key, "initializer");
  v.Check(o);
}

// `initializer`: when an anchor's initializer may solve at all, and how much it keeps.
template <typename V>
void Initializer(V& v, estimator::InitializerOptions& o) {
  v.Integer("min_samples", o.min_samples);
  v.Number("retry_growth", o.retry_growth);
  v.Integer("max_buffered_samples", o.max_buffered_samples);
  v.Choice("at_cap", o.at_cap, estimator::kBufferPolicyNames);
  v.Check(o);
}

template <typename V>
void Ls(V& v, estimator::LsOptions& o) {
  v.Choice("method", o.method, estimator::kLsMethodNames);
  v.Choice("pivot", o.pivot, estimator::kLsPivotNames);
  v.Number("sigma_range_m", o.sigma_range_m);
  v.Number("sigma_position_m", o.sigma_position_m);
  v.Check(o);
}

template <typename V>
void Nls(V& v, estimator::NlsOptions& o) {
  v.Choice("kernel", o.kernel, estimator::kKernelModeNames);
  v.Number("fixed_alpha", o.fixed_alpha);
  v.Number("alpha_min", o.alpha_min);
  v.Number("kernel_scale_m", o.kernel_scale_m);
  v.Number("truncation", o.truncation);
  v.Integer("max_iterations", o.max_iterations);
  v.Number("step_tolerance_m", o.step_tolerance_m);
  v.Number("alpha_tolerance", o.alpha_tolerance);
  v.Number("initial_damping", o.initial_damping);
  v.Flag("l2_warm_start", o.l2_warm_start);
  v.Integer("max_passes", o.max_passes);
  v.Check(o);
}

// What a covariance adds beyond the solver's (estimator.covariance, and the certificate's own).
template <typename V>
void Covariance(V& v, estimator::CovarianceOptions& o) {
  v.Number("model_error_m", o.model_error_m);
  v.Integer("model_error_degree", o.model_error_degree);
  v.Flag("travel_bias", o.travel_bias);
  v.Number("link_offset_m", o.link_offset_m);
  v.Flag("correlated_noise", o.correlated_noise);
  v.Check(o);
}

template <typename V>
void Estimator(V& v, schema::EstimatorConfig& o, const registry::Components& components) {
  v.Name("solver", o.solver, [&](const std::string& name, std::string* why) { return components.solvers.Knows(name, why); });
  v.NameList("triggers", o.triggers,
             [&](const std::string& name, std::string* why) { return components.triggers.Knows(name, why); });
  v.Flag("oracle_latency", o.oracle_latency);
  v.Section("filter", [&](auto& s) { Filter(s, o.filter, components); });
  v.Section("initializer", [&](auto& s) { Initializer(s, o.initializer); });
  v.Section("trigger", [&](auto& s) { Trigger(s, o.trigger); });
  v.Section("ls", [&](auto& s) { Ls(s, o.solver_options.ls); });
  v.Section("nls", [&](auto& s) { Nls(s, o.solver_options.nls); });
  v.Section("height_check", [&](auto& s) {
    s.Flag("enabled", o.initializer.height_check.enabled);
    s.Number("min_evidence", o.initializer.height_check.min_evidence);
    s.Number("min_separation", o.initializer.height_check.min_separation);
    s.Number("trim_fraction", o.initializer.height_check.trim_fraction);
    s.Choice("side", o.initializer.height_check.side, estimator::kSideNames);
    s.Check(o.initializer.height_check);
  });
  v.Section("certificate", [&](auto& s) {
    s.Number("accuracy_m", o.certificate.accuracy_m);
    s.Number("confidence", o.certificate.confidence);
    s.Number("evaluate_growth", o.certificate.evaluate_growth);
    s.Number("stable_since", o.certificate.stable_since);
    s.Flag("region_ends", o.certificate.region_ends);
    Covariance(s, o.certificate.covariance);
    s.Check(o.certificate);
  });
  v.Section("covariance", [&](auto& s) { Covariance(s, o.initializer.covariance); });
  v.Section("tag_biases", [&](auto& s) {
    s.Flag("estimate", o.initializer.tag_biases.estimate);
    s.Integer("iterations", o.initializer.tag_biases.iterations);
    s.Check(o.initializer.tag_biases);
  });
  v.Section("scale", [&](auto& s) {
    s.Flag("estimate", o.solver_options.scale.estimate);
    s.Number("max_sigma", o.solver_options.scale.max_sigma);
    s.Number("max_scale", o.solver_options.scale.max_scale);
    s.Check(o.solver_options.scale);
  });
  v.Section("height_prior", [&](auto& s) {
    s.Flag("enabled", o.height_prior.enabled);
    s.Number("sigma_m", o.height_prior.sigma_m);
    s.Number("z_m", o.height_prior.z_m);
    s.Flag("from_reference", o.height_prior.from_reference);
    s.Number("offset_m", o.height_prior.offset_m);
    s.Check(o.height_prior);
  });
  // Last: a part's section may not shadow one of the keys above.
  std::vector<std::string> named = o.triggers;
  named.push_back(o.solver);
  named.push_back(o.filter.kind);
  v.PartOptions(o.part_options, named, components.PartsWithOptions());
}

template <typename V>
void Cells(V& v, schema::PaperCells& cells) {
  constexpr Bounds kNonNegative{0.0};
  v.Number("avg_m", cells.avg_m, kNonNegative);
  v.Number("med_m", cells.med_m, kNonNegative);
  v.Number("init", cells.init, kNonNegative);
  v.Number("gt1m", cells.gt1m, kNonNegative);
  v.Number("ratio_pct", cells.ratio_pct, {0.0, 100.0});
}

template <typename V>
void Row(V& v, schema::RowConfig& row, const registry::Components& components) {
  v.Label("name", row.name);
  v.Section("scenario", [&](auto& s) { Scenario(s, row.scenario, components); });
  v.Section("estimator", [&](auto& s) { Estimator(s, row.estimator, components); });
  v.OptionalSection("paper", row.paper, [](auto& s, schema::PaperRow& paper) {
    s.Section("fixed", [&](auto& cells) { Cells(cells, paper.fixed); });
    s.Section("gated", [&](auto& cells) { Cells(cells, paper.gated); });
  });
}

template <typename V>
void Navigation(V& v, schema::NavigationConfig& o) {
  v.Number("sigma_bias_mps_per_sqrt_s", o.sigma_bias_mps_per_sqrt_s);
  v.Number("sigma_heading_rad_per_sqrt_s", o.sigma_heading_rad_per_sqrt_s);
  v.Number("sigma_step_m_per_sqrt_s", o.sigma_step_m_per_sqrt_s);
  v.Number("sigma_start_m", o.sigma_start_m);
  v.Number("sigma_range_m", o.sigma_range_m);
  v.Number("gate_chi2", o.gate_chi2);
  v.Integer("fix_anchors", o.fix_anchors);
  v.Integer("kth_anchor", o.kth_anchor);
  v.Number("error_bin_s", o.error_bin_s);
  v.Choice("height_unobservable", o.height_unobservable, schema::kMirroredAnchorUseNames);
  v.Check(o);
}

template <typename V>
void PdopStudy(V& v, schema::PdopStudyConfig& o) {
  v.Integer("every", o.every, 1, 1000000);
  v.Number("bin_s", o.bin_s);
  v.Check(o);
}

template <typename V>
void Exploration(V& v, schema::ExplorationConfig& o, const registry::Components& components) {
  v.NameList("policies", o.policies, [](const std::string& name, std::string* why) {
    schema::ExplorationConfig one;
    one.policies = {name};
    if (one.IsValid(nullptr)) return true;
    if (why) *why = "unknown policy '" + name + "' (pattern, guided, oracle, dop_waypoints)";
    return false;
  });
  v.Name("trigger", o.trigger, [&](const std::string& name, std::string* why) { return components.triggers.Knows(name, why); });
  v.Number("max_duration_s", o.max_duration_s);
  v.Number("decision_period_s", o.decision_period_s);
  v.Number("reach_m", o.reach_m);
  v.Integer("grid_steps", o.grid_steps);
  v.Number("dwell_s", o.dwell_s);
  v.Integer("detours_per_anchor", o.detours_per_anchor);
  v.Number("speed_mps", o.speed_mps);
  v.Number("plan_after_s", o.plan_after_s);
  v.Integer("waypoints", o.waypoints);
  v.Number("clearance_m", o.clearance_m);
  v.Flag("vertical", o.vertical);
  v.Check(o);
}

template <typename V>
void Experiment(V& v, schema::ExperimentConfig& c, const registry::Components& components) {
  v.Unsigned("seed", c.seed, schema::kMaxSeed);
  v.Integer("realizations", c.realizations, 1, 100000000);
  v.Integer("bootstrap_resamples", c.bootstrap_resamples, 0, 1000000);
  v.Section("scenario", [&](auto& s) { Scenario(s, c.scenario, components); });
  v.Section("estimator", [&](auto& s) { Estimator(s, c.estimator, components); });
  v.TextList("only_rows", c.only_rows);
  v.TextMap("sweep", c.sweep);
  v.OptionalSection("navigation", c.navigation, [](auto& s, schema::NavigationConfig& o) { Navigation(s, o); });
  v.OptionalSection("exploration", c.exploration,
                    [&](auto& s, schema::ExplorationConfig& o) { Exploration(s, o, components); });
  v.OptionalSection("pdop_study", c.pdop_study, [](auto& s, schema::PdopStudyConfig& o) { PdopStudy(s, o); });
  // Rows start from the base read above, so the base must come first in the visit.
  int index = 0;
  v.List("rows", c.rows,
         [&] { return schema::RowConfig{std::to_string(++index), c.scenario, c.estimator, std::nullopt}; },
         [&](auto& s, schema::RowConfig& row) { Row(s, row, components); });
}

}  // namespace anchorbench::config::visit
