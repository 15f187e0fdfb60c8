#include "anchorbench/engine/exploration.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "anchorbench/engine/attempt.hpp"
#include "anchorbench/engine/executor.hpp"
#include "anchorbench/engine/monte_carlo.hpp"
#include "anchorbench/engine/navigation.hpp"
#include "anchorbench/estimator/front_end.hpp"
#include "anchorbench/estimator/guide.hpp"
#include "anchorbench/report/navigation_report.hpp"
#include "anchorbench/report/run_outputs.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/schema/random_streams.hpp"
#include "anchorbench/sim/range_draws.hpp"
#include "anchorbench/sim/scenario.hpp"
#include "dop_waypoints.hpp"
#include "exploration_body.hpp"

namespace anchorbench::engine {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The environment's box shrunk by the clearance: where a detour may go.
struct FreeSpace {
  Eigen::Vector3d low, high;
  bool Holds(const Eigen::Vector3d& p) const { return (p.array() >= low.array()).all() && (p.array() <= high.array()).all(); }
};

FreeSpace FreeSpaceOf(const sim::ScenarioOptions& scenario, double clearance_m) {
  const Eigen::Vector3d margin = Eigen::Vector3d::Constant(clearance_m);
  if (scenario.environment == sim::EnvironmentKind::kTunnel) {
    const sim::TunnelOptions& t = scenario.tunnel;
    return {Eigen::Vector3d(0.0, -0.5 * t.width_m, 0.0) + margin, Eigen::Vector3d(t.length_m, 0.5 * t.width_m, t.height_m) - margin};
  }
  const sim::HallOptions& h = scenario.hall;
  return {margin, Eigen::Vector3d(h.length_m, h.width_m, h.height_m) - margin};
}

// The candidates within reach of the body: a grid inside the free space, at the body's height
// for a robot without vertical reach.
std::vector<Eigen::Vector3d> CandidatesAround(const Eigen::Vector3d& p_world_body, const schema::ExplorationConfig& ex,
                                              const FreeSpace& space) {
  std::vector<Eigen::Vector3d> candidates;
  for (const Eigen::Vector3d& p : estimator::CandidateGrid(p_world_body, ex.reach_m, ex.grid_steps)) {
    if (space.Holds(p) && (ex.vertical || std::abs(p.z() - p_world_body.z()) < 1e-9)) candidates.push_back(p);
  }
  return candidates;
}

// The oracle's guidance: the certificate's own forecast (its noise, its D), taken at the true
// anchor instead of the estimate, for each anchor still waiting.
std::vector<estimator::AnchorGuidance> OracleGuidance(const estimator::FrontEnd& front_end,
                                                      const estimator::GuideRequest& request,
                                                      const std::map<int, schema::AnchorTruth>& truth) {
  std::vector<estimator::AnchorGuidance> guidance;
  for (const int anchor_id : front_end.anchor_ids()) {
    const estimator::AnchorInitializer& chain = front_end.chains(anchor_id).front();
    const std::optional<estimator::RegionForecast> forecast = chain.Forecast();
    if (!forecast) continue;
    estimator::RegionBasis basis = forecast->basis();
    basis.p_world_anchor = truth.at(anchor_id).p_world_anchor;
    const estimator::RegionForecast at_truth(basis, chain.p_world_tag(), chain.tag_id());
    estimator::AnchorGuidance g;
    g.anchor_id = anchor_id;
    g.region_m = at_truth.region_m();
    g.accuracy_m = basis.accuracy_m;
    g.best = at_truth.Rank(request.p_world_candidate, request.samples, request.best);
    guidance.push_back(std::move(g));
  }
  return guidance;
}

// The candidate that certifies a waiting anchor soonest (the flight there at speed_mps plus its
// forecast samples at the link's rate), among those forecast to certify it within the dwell; none
// otherwise: a detour costs the pattern's progress, so it is flown only where the forecast says
// it pays. An anchor whose region is within D already waits for a test the forecast does not see
// (the mirror, an alternative, the stability): no detour for it either. Nor for an anchor that had
// detours_per_anchor detours already: the forecast was wrong for it, and more would stall the
// pattern (docs/guidance.md).
struct Detour {
  int anchor_id = 0;
  Eigen::Vector3d p_world_candidate;
};
std::optional<Detour> Soonest(const std::vector<estimator::AnchorGuidance>& guidance, const Eigen::Vector3d& p_world_body,
                              const schema::ExplorationConfig& ex, double samples, double rate_hz,
                              const std::map<int, int>& detours_of) {
  std::optional<Detour> soonest;
  double soonest_s = kInf;
  for (const estimator::AnchorGuidance& anchor : guidance) {
    if (!(anchor.region_m > anchor.accuracy_m)) continue;  // held by another test
    if (const auto had = detours_of.find(anchor.anchor_id); had != detours_of.end() && had->second >= ex.detours_per_anchor) {
      continue;
    }
    for (const estimator::CandidateForecast& c : anchor.best) {
      if (!(c.samples_to_certify <= samples)) continue;
      const double total_s = (c.p_world_candidate - p_world_body).norm() / ex.speed_mps + c.samples_to_certify / rate_hz;
      if (total_s < soonest_s) {
        soonest_s = total_s;
        soonest = Detour{anchor.anchor_id, c.p_world_candidate};
      }
    }
  }
  return soonest;
}

// A policy's next detour, if it takes one: guided asks guidance (estimator::Guide) as a robot
// would, the oracle the forecast at the truth.
std::optional<Detour> NextDetour(const estimator::FrontEnd& front_end, const Eigen::Vector3d& p_world_body,
                                 const schema::ExplorationConfig& ex, const FreeSpace& space, double rate_hz,
                                 const std::map<int, int>& detours_of, const std::map<int, schema::AnchorTruth>* truth) {
  estimator::GuideRequest request;
  request.p_world_candidate = CandidatesAround(p_world_body, ex, space);
  if (request.p_world_candidate.empty()) return std::nullopt;
  request.samples = std::max(1.0, ex.dwell_s * rate_hz);
  request.range_rate_hz = rate_hz;
  const std::vector<estimator::AnchorGuidance> guidance =
      truth ? OracleGuidance(front_end, request, *truth) : estimator::Guide(front_end, request);
  return Soonest(guidance, p_world_body, ex, request.samples, rate_hz, detours_of);
}

// The waypoints' candidates: a grid over the free space at `spacing_m` (at `z_m` without vertical
// reach), coarsened by half steps until it has at most kMaxPlanPoints points, so that a large
// environment with a fine reach costs a bounded plan.
std::vector<Eigen::Vector3d> PlanGrid(const FreeSpace& space, double spacing_m, bool vertical, double z_m) {
  constexpr double kMaxPlanPoints = 1e5;
  const Eigen::Array3d extent = (space.high - space.low).array().max(0.0);
  auto points_along = [&](double spacing) {
    Eigen::Array3d n = (extent / spacing).floor() + 1.0;
    if (!vertical) n.z() = 1.0;
    return n;
  };
  while (!(points_along(spacing_m).prod() <= kMaxPlanPoints)) spacing_m *= 1.5;
  const Eigen::Array3i n = points_along(spacing_m).cast<int>();
  std::vector<Eigen::Vector3d> grid;
  for (int i = 0; i < n.x(); ++i) {
    for (int j = 0; j < n.y(); ++j) {
      for (int k = 0; k < n.z(); ++k) {
        Eigen::Vector3d p = space.low + spacing_m * Eigen::Vector3d(i, j, k);
        if (!vertical) p.z() = z_m;
        grid.push_back(p);
      }
    }
  }
  return grid;
}

// The offline-waypoint baseline's route (dop_waypoints.hpp): waypoints on PlanGrid at the
// candidates' spacing, planned at each waiting anchor's estimate so far (the certificate's last),
// nearest first.
std::vector<Eigen::Vector3d> PlanRoute(const estimator::FrontEnd& front_end, const Eigen::Vector3d& p_world_body,
                                       const schema::ExplorationConfig& ex, const FreeSpace& space, double rate_hz) {
  std::vector<PlannedAnchor> anchors;
  for (const int anchor_id : front_end.anchor_ids()) {
    const estimator::AnchorInitializer& chain = front_end.chains(anchor_id).front();
    if (const std::optional<estimator::RegionForecast> forecast = chain.Forecast()) {
      const Eigen::Vector3d& p_world_anchor = forecast->basis().p_world_anchor;
      anchors.push_back({p_world_anchor, RangeInformation(chain.p_world_tag(), p_world_anchor)});
    }
  }
  const std::vector<Eigen::Vector3d> grid = PlanGrid(space, ex.reach_m / ex.grid_steps, ex.vertical, p_world_body.z());
  return PlanDopWaypoints(std::move(anchors), grid, ex.waypoints, std::max(1.0, ex.dwell_s * rate_hz), p_world_body);
}

// One policy's run on the realization's anchors and pattern.
ExplorationRecord RunPolicy(const schema::RowConfig& row, std::uint64_t seed, int realization,
                            const schema::ExplorationConfig& ex, const registry::Components& components,
                            const std::vector<sim::SimAnchor>& anchors, const std::vector<Eigen::Vector3d>& pattern,
                            const std::string& policy, const std::optional<schema::NavigationConfig>& navigation) {
  const sim::ScenarioOptions& scenario = row.scenario;
  const double rate_hz = scenario.trajectory.rate_hz, dt = 1.0 / rate_hz;
  std::map<int, schema::AnchorTruth> truth;
  for (const sim::SimAnchor& anchor : anchors) truth[anchor.id] = {anchor.p_world_anchor, anchor.bias_m};
  estimator::FrontEnd front_end([&](int anchor_id) {
    std::vector<estimator::AnchorInitializer> chain;
    chain.push_back(registry::MakeInitializer(components, anchor_id, row.estimator, ex.trigger,
                                              SolverSeed(seed, static_cast<std::uint64_t>(realization), anchor_id),
                                              truth.at(anchor_id).p_world_anchor));
    return chain;
  });
  for (const sim::SimAnchor& anchor : anchors) front_end.AddAnchor(anchor.id);
  // Every policy draws from the same streams: the same link noise, outliers and position errors.
  sim::RangeDraws draws(scenario.ranging, seed, static_cast<std::uint64_t>(realization), scenario.tag_offsets_m.size(),
                        anchors);
  sim::TagPlacement placement(scenario, seed, static_cast<std::uint64_t>(realization));
  const FreeSpace space = FreeSpaceOf(scenario, ex.clearance_m);
  Body body(pattern, ex.speed_mps * dt);

  ExplorationRecord record;
  record.policy = policy;
  const bool detours = policy == schema::kGuidedPolicy || policy == schema::kOraclePolicy;
  bool plans = policy == schema::kDopWaypointsPolicy;  // once, at plan_after_s
  const std::map<int, schema::AnchorTruth>* oracle = policy == schema::kOraclePolicy ? &truth : nullptr;
  record.anchors = static_cast<int>(anchors.size());
  const double accuracy_m = row.estimator.certificate.accuracy_m;
  std::vector<Eigen::Vector3d> p_true, p_reported;
  std::vector<sim::SimRange> ranges;
  double next_decision_s = ex.decision_period_s;
  std::map<int, int> detours_of;  // detours flown for each anchor
  // With a navigation section, the run goes on to max_duration_s (the same time for every policy)
  // and tag 0's flight, its ranges and the certified anchors go to the navigation filter after.
  Trajectory flown;
  std::vector<nav::UsableAnchor> usable;
  const auto epochs = static_cast<std::size_t>(std::floor(ex.max_duration_s * rate_hz)) + 1;
  for (std::size_t k = 0; k < epochs; ++k) {
    const double t_s = static_cast<double>(k) * dt;
    // This epoch's ranges where the body is, to the front end.
    placement.Next(body.p_world_body(), body.yaw_rad(), &p_true, &p_reported);
    ranges.clear();
    draws.Epoch(k, t_s, p_true, body.yaw_rad(), &ranges);
    for (const sim::SimRange& r : ranges) {
      front_end.AddSample({r.t_s, r.tag_id, r.anchor_id, r.range_m, p_reported[static_cast<std::size_t>(r.tag_id)]});
      if (navigation && r.tag_id == 0) flown.ranges.push_back({k, r.anchor_id, r.range_m});
    }
    if (navigation) {
      flown.t_s.push_back(t_s);
      flown.p_world_tag.push_back(p_true.front());
    }
    // The certified anchors, judged against the truth.
    for (const estimator::FrontEndEvent& event : front_end.TakeEvents()) {
      if (event.kind != estimator::FrontEndEvent::Kind::kInitialized) continue;
      const double error_m = (event.init.solve.p_world_anchor - truth.at(event.anchor_id).p_world_anchor).norm();
      ++record.certified;
      if (error_m > accuracy_m) ++record.beyond_accuracy;
      record.max_error_m = std::max(record.max_error_m, error_m);
      const estimator::SolveResult& solve = event.init.solve;
      usable.push_back({event.anchor_id, t_s, solve.p_world_anchor, solve.bias_m, solve.covariance, false});
    }
    record.duration_s = t_s;
    if (record.certified == record.anchors && record.t_all_certified_s < 0.0) {
      record.t_all_certified_s = t_s;
      record.distance_m = body.distance_m();
      if (!navigation) break;
    }
    // The offline baseline: its waypoints, planned once.
    if (plans && body.on_pattern() && t_s >= ex.plan_after_s) {
      plans = false;
      std::vector<Eigen::Vector3d> route = PlanRoute(front_end, body.p_world_body(), ex, space, rate_hz);
      record.detours = static_cast<int>(route.size());
      body.Visit(std::move(route), static_cast<int>(std::ceil(ex.dwell_s * rate_hz)));
    }
    // Guided and oracle: a detour when one is due and a candidate is worth it.
    if (detours && body.on_pattern() && t_s >= next_decision_s) {
      next_decision_s = t_s + ex.decision_period_s;
      if (const std::optional<Detour> detour =
              NextDetour(front_end, body.p_world_body(), ex, space, rate_hz, detours_of, oracle)) {
        body.Visit({detour->p_world_candidate}, static_cast<int>(std::ceil(ex.dwell_s * rate_hz)));
        ++detours_of[detour->anchor_id];
        ++record.detours;
      }
    }
    body.Step();
  }
  if (record.t_all_certified_s < 0.0) record.distance_m = body.distance_m();
  if (navigation) {
    sim::RandomStream rng(seed, static_cast<std::uint64_t>(realization), schema::kNavigationStream);
    nav::NavigationOutcome outcome =
        NavigateMethods(flown, {{policy, usable}}, OptionsOf(*navigation, scenario.ranging.sigma_range_m), rng, 0,
                        realization)
            .front()
            .outcome;
    record.navigation_rmse_m = outcome.rmse_m;
    record.navigation_error_by_bin_m = std::move(outcome.error_by_bin_m);
  }
  return record;
}

}  // namespace

void CheckExploration(const schema::ExperimentConfig& config, const registry::Components& components) {
  if (!config.exploration) {
    throw schema::InputError("config " + config.name + ": no 'exploration' section (docs/guidance.md)");
  }
  CheckExperiment(config, components);
  if (config.navigation) CheckErrorBins(config.exploration->max_duration_s, *config.navigation, config.name);
  for (const schema::RowConfig& row : schema::RowsOf(config)) {
    const double epochs = config.exploration->max_duration_s * row.scenario.trajectory.rate_hz + 1.0;
    if (!(epochs * row.scenario.tag_offsets_m.size() <= sim::ScenarioOptions::kMaxTagEpochs)) {
      throw schema::InputError("row " + row.name + ": exploration.max_duration_s x scenario.trajectory.rate_hz x tags "
                               "exceeds 1e7 tag epochs: shorten the run");
    }
  }
}

std::vector<ExplorationRecord> ExploreRealization(const schema::RowConfig& row, int row_index, std::uint64_t seed,
                                                  int realization, const schema::ExplorationConfig& exploration,
                                                  const std::optional<schema::NavigationConfig>& navigation,
                                                  const registry::Components& components) {
  const std::vector<sim::SimAnchor> anchors = sim::DrawAnchors(row.scenario, seed, static_cast<std::uint64_t>(realization));
  const sim::Trajectory pattern = sim::DrawBodyPath(row.scenario, anchors, seed, static_cast<std::uint64_t>(realization));
  std::vector<ExplorationRecord> records;
  for (const std::string& policy : exploration.policies) {
    records.push_back(
        RunPolicy(row, seed, realization, exploration, components, anchors, pattern.p_world_tag, policy, navigation));
    records.back().row = row_index;
    records.back().realization = realization;
  }
  return records;
}

std::vector<ExplorationRecord> RunExploration(const schema::ExperimentConfig& config,
                                              const registry::Components& components, int threads,
                                              const RunControl& control) {
  CheckExploration(config, components);
  const std::vector<schema::RowConfig> rows = schema::RowsOf(config);
  const std::function<std::vector<ExplorationRecord>(int)> unit = [&](int u) {
    const int row = u / config.realizations;
    return ExploreRealization(rows[static_cast<std::size_t>(row)], row, config.seed, u % config.realizations,
                              *config.exploration, config.navigation, components);
  };
  return ParallelRecords(static_cast<int>(rows.size()) * config.realizations, threads, unit, control);
}

namespace {

struct PolicySummary {
  int row = 0;
  std::string policy;
  int runs = 0, all_certified = 0, anchors = 0, certified = 0, beyond_accuracy = 0;
  double median_t_all_s = kInf;  // over the runs, a run not all certified counting as +inf
  double max_error_m = 0.0, mean_distance_m = 0.0, mean_detours = 0.0;
  double mean_navigation_rmse_m = -1.0;  // -1: not navigated
};

double Median(std::vector<double> values) {
  if (values.empty()) return kInf;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::vector<PolicySummary> Summarize(const std::vector<ExplorationRecord>& records, const schema::ExplorationConfig& ex,
                                     int rows) {
  std::vector<PolicySummary> summaries;
  for (int row = 0; row < rows; ++row) {
    for (const std::string& policy : ex.policies) {
      PolicySummary s;
      s.row = row;
      s.policy = policy;
      std::vector<double> t_all;
      double rmse_sum_m = 0.0;
      int navigated = 0;
      for (const ExplorationRecord& r : records) {
        if (r.row != row || r.policy != policy) continue;
        ++s.runs;
        s.anchors += r.anchors;
        s.certified += r.certified;
        s.beyond_accuracy += r.beyond_accuracy;
        s.max_error_m = std::max(s.max_error_m, r.max_error_m);
        s.mean_distance_m += r.distance_m;
        s.mean_detours += r.detours;
        if (r.t_all_certified_s >= 0.0) ++s.all_certified;
        if (r.navigation_rmse_m >= 0.0) {
          rmse_sum_m += r.navigation_rmse_m;
          ++navigated;
        }
        t_all.push_back(r.t_all_certified_s >= 0.0 ? r.t_all_certified_s : kInf);
      }
      if (s.runs > 0) {
        s.mean_distance_m /= s.runs;
        s.mean_detours /= s.runs;
      }
      if (navigated > 0) s.mean_navigation_rmse_m = rmse_sum_m / navigated;
      s.median_t_all_s = Median(t_all);
      summaries.push_back(s);
    }
  }
  return summaries;
}

std::string Fixed(double value, int digits) {
  if (!std::isfinite(value)) return "inf";
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << value;
  return out.str();
}

}  // namespace

std::string WriteExplorationFiles(const FileWriter& write, const schema::ExperimentConfig& config,
                                  const std::vector<ExplorationRecord>& records, const report::RunInfo& info) {
  const std::vector<schema::RowConfig> rows = schema::RowsOf(config);
  write("exploration.csv", [&](std::ostream& file) {
    file << "row,realization,policy,anchors,certified,beyond_accuracy,max_error_m,t_all_certified_s,duration_s,"
            "distance_m,detours,navigation_rmse_m\n";
    for (const ExplorationRecord& r : records) {
      file << rows[static_cast<std::size_t>(r.row)].name << ',' << r.realization << ',' << r.policy << ',' << r.anchors << ','
           << r.certified << ',' << r.beyond_accuracy << ',' << Fixed(r.max_error_m, 4) << ','
           << (r.t_all_certified_s >= 0.0 ? Fixed(r.t_all_certified_s, 1) : "") << ',' << Fixed(r.duration_s, 1) << ','
           << Fixed(r.distance_m, 2) << ',' << r.detours << ','
           << (r.navigation_rmse_m >= 0.0 ? Fixed(r.navigation_rmse_m, 4) : "") << '\n';
    }
  });
  const std::vector<PolicySummary> summaries = Summarize(records, *config.exploration, static_cast<int>(rows.size()));
  write("exploration_summary.csv", [&](std::ostream& file) {
    file << "row,policy,runs,all_certified_runs,median_t_all_certified_s,anchors,certified,beyond_accuracy,"
            "max_error_m,mean_distance_m,mean_detours,mean_navigation_rmse_m\n";
    for (const PolicySummary& s : summaries) {
      file << rows[static_cast<std::size_t>(s.row)].name << ',' << s.policy << ',' << s.runs << ',' << s.all_certified << ','
           << Fixed(s.median_t_all_s, 1) << ',' << s.anchors << ',' << s.certified << ',' << s.beyond_accuracy << ','
           << Fixed(s.max_error_m, 3) << ',' << Fixed(s.mean_distance_m, 1) << ',' << Fixed(s.mean_detours, 1) << ','
           << (s.mean_navigation_rmse_m >= 0.0 ? Fixed(s.mean_navigation_rmse_m, 3) : "") << '\n';
    }
  });
  std::ostringstream md;
  md << "# " << config.name << ": closed-loop exploration\n\n"
     << "Time until every anchor is certified (trigger `" << config.exploration->trigger << "`, D = "
     << Fixed(rows.front().estimator.certificate.accuracy_m, 2) << " m), per policy; a run that ends at "
     << Fixed(config.exploration->max_duration_s, 0) << " s with an anchor waiting counts as inf in the median.\n\n"
     << "| row | policy | runs all certified | median time to certify all (s) | anchors certified | beyond D | "
        "max error (m) | mean distance (m) | mean detours | mean navigation RMSE (m) |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const PolicySummary& s : summaries) {
    md << "| " << rows[static_cast<std::size_t>(s.row)].name << " | " << s.policy << " | " << s.all_certified << " / "
       << s.runs << " | " << Fixed(s.median_t_all_s, 1) << " | " << s.certified << " / " << s.anchors << " | "
       << s.beyond_accuracy << " | " << Fixed(s.max_error_m, 2) << " | " << Fixed(s.mean_distance_m, 0) << " | "
       << Fixed(s.mean_detours, 1) << " | "
       << (s.mean_navigation_rmse_m >= 0.0 ? Fixed(s.mean_navigation_rmse_m, 3) : "-") << " |\n";
  }
  write("exploration.md", [&](std::ostream& file) { file << md.str(); });
  if (config.navigation) {
    std::vector<nav::NavigationRecord> navigated;
    for (const ExplorationRecord& r : records) {
      nav::NavigationRecord n{r.row, r.realization, r.policy, {}};
      n.outcome.error_by_bin_m = r.navigation_error_by_bin_m;
      navigated.push_back(std::move(n));
    }
    write("navigation_error.csv", [&](std::ostream& file) {
      report::WriteNavigationErrorCsv(file, navigated, rows, config.navigation->error_bin_s);
    });
  }
  write("manifest.json", [&](std::ostream& file) { file << report::ManifestJson(config, info); });
  return md.str();
}

}  // namespace anchorbench::engine
