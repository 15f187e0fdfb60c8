#include "anchorbench/studies/exploration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "anchorbench/engine/attempt.hpp"
#include "anchorbench/engine/executor.hpp"
#include "anchorbench/studies/exploration_lines.hpp"
#include "anchorbench/engine/monte_carlo.hpp"
#include "anchorbench/studies/navigation.hpp"
#include "anchorbench/engine/unit_records.hpp"
#include "anchorbench/estimator/front_end.hpp"
#include "anchorbench/estimator/guide.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/schema/random_streams.hpp"
#include "anchorbench/sim/range_draws.hpp"
#include "anchorbench/sim/scenario.hpp"
#include "dop_waypoints.hpp"
#include "exploration_body.hpp"

namespace anchorbench::studies {

using engine::CheckExperiment;
using engine::RecordJournal;
using engine::RunControl;
using engine::RunUnitRecords;
using engine::Shard;
using engine::SolverSeed;
using engine::TruthOf;
using engine::UnitRecords;
namespace {


// The environment's box shrunk by the clearance: where a detour may go.
struct FreeSpace {
  Eigen::Vector3d low, high;
  bool Holds(const Eigen::Vector3d& p) const { return (p.array() >= low.array()).all() && (p.array() <= high.array()).all(); }
};

FreeSpace FreeSpaceOf(const sim::ScenarioOptions& scenario, double clearance_m) {
  const Eigen::Vector3d margin = Eigen::Vector3d::Constant(clearance_m);
  const sim::Environment::Box bounds = scenario.MakeEnvironment()->Bounds();
  return {bounds.low + margin, bounds.high - margin};
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
  double soonest_s = std::numeric_limits<double>::infinity();
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
      anchors.push_back(PlannedAt(p_world_anchor, chain.p_world_tag()));
    }
  }
  const std::vector<Eigen::Vector3d> grid = PlanGrid(space, ex.reach_m / ex.grid_steps, ex.vertical, p_world_body.z());
  return PlanDopWaypoints(std::move(anchors), grid, ex.waypoints, std::max(1.0, ex.dwell_s * rate_hz), p_world_body);
}

// The realization one policy flies: its row, anchors and pattern, and the streams they came from.
struct Realization {
  const schema::RowConfig& row;
  std::uint64_t seed;
  int index;
  const std::vector<sim::SimAnchor>& anchors;
  const std::vector<Eigen::Vector3d>& pattern;
};

// One policy's run, epoch by epoch: the ranges drawn where the body is and fed to the front end,
// the certified anchors judged against the truth, the policy's decision, one step of the body.
class PolicyRun {
 public:
  PolicyRun(const Realization& r, const schema::ExplorationConfig& ex, const registry::Components& components,
            const std::string& policy, bool navigated)
      : r_(r),
        ex_(ex),
        rate_hz_(r.row.scenario.trajectory.rate_hz),
        dt_s_(1.0 / rate_hz_),
        navigated_(navigated),
        truth_(TruthOf(r.anchors)),
        front_end_(ChainsOf(r, ex, components, truth_)),
        // Every policy draws from the same streams: the same link noise, outliers and position errors.
        draws_(r.row.scenario.ranging, r.seed, static_cast<std::uint64_t>(r.index), r.row.scenario.tag_offsets_m.size(),
               r.anchors),
        placement_(r.row.scenario, r.seed, static_cast<std::uint64_t>(r.index)),
        space_(FreeSpaceOf(r.row.scenario, ex.clearance_m)),
        body_(r.pattern, ex.speed_mps * dt_s_),
        detours_(policy == schema::kGuidedPolicy || policy == schema::kOraclePolicy),
        plans_(policy == schema::kDopWaypointsPolicy),
        oracle_(policy == schema::kOraclePolicy ? &truth_ : nullptr),
        next_decision_s_(ex.decision_period_s) {
    for (const sim::SimAnchor& anchor : r.anchors) front_end_.AddAnchor(anchor.id);
    record_.realization = r.index;
    record_.policy = policy;
    record_.anchors = static_cast<int>(r.anchors.size());
  }

  // Until every anchor is certified, or (navigated: the same time for every policy) to the end.
  ExplorationRecord Run(const std::optional<schema::NavigationConfig>& navigation) {
    const auto epochs = static_cast<std::size_t>(std::floor(ex_.max_duration_s * rate_hz_)) + 1;
    for (std::size_t k = 0; k < epochs; ++k) {
      const double t_s = static_cast<double>(k) * dt_s_;
      RangeFromBody(k, t_s);
      TakeCertified(t_s);
      if (record_.certified == record_.anchors && record_.t_all_certified_s < 0.0) {
        record_.t_all_certified_s = t_s;
        record_.distance_m = body_.distance_m();
        if (!navigated_) break;
      }
      Decide(t_s);
      body_.Step();
    }
    if (record_.t_all_certified_s < 0.0) record_.distance_m = body_.distance_m();
    if (navigation) Navigate(*navigation);
    return std::move(record_);
  }

 private:
  static std::map<int, schema::AnchorTruth> TruthOf(const std::vector<sim::SimAnchor>& anchors) {
    std::map<int, schema::AnchorTruth> truth;
    for (const sim::SimAnchor& anchor : anchors) truth[anchor.id] = {anchor.p_world_anchor, anchor.bias_m};
    return truth;
  }

  static estimator::FrontEnd::ChainFactory ChainsOf(const Realization& r, const schema::ExplorationConfig& ex,
                                                    const registry::Components& components,
                                                    const std::map<int, schema::AnchorTruth>& truth) {
    return [&r, &ex, &components, &truth](int anchor_id) {
      std::vector<estimator::AnchorInitializer> chain;
      chain.push_back(registry::MakeInitializer(components, anchor_id, r.row.estimator, ex.trigger,
                                                SolverSeed(r.seed, static_cast<std::uint64_t>(r.index), anchor_id),
                                                truth.at(anchor_id).p_world_anchor));
      return chain;
    };
  }

  // This epoch's ranges where the body is, to the front end (and tag 0's to the navigation after).
  void RangeFromBody(std::size_t k, double t_s) {
    placement_.Next(body_.p_world_body(), body_.yaw_rad(), &p_true_, &p_reported_);
    ranges_.clear();
    draws_.Epoch(k, t_s, p_true_, body_.yaw_rad(), &ranges_);
    for (const sim::SimRange& range : ranges_) {
      front_end_.AddSample(
          {range.t_s, range.tag_id, range.anchor_id, range.range_m, p_reported_[static_cast<std::size_t>(range.tag_id)]});
      if (navigated_ && range.tag_id == 0) flown_.ranges.push_back({k, range.anchor_id, range.range_m});
    }
    if (navigated_) {
      flown_.t_s.push_back(t_s);
      flown_.p_world_tag.push_back(p_true_.front());
    }
    record_.duration_s = t_s;
  }

  // The anchors certified this epoch, judged against the truth, and usable by the navigation.
  void TakeCertified(double t_s) {
    for (const estimator::FrontEndEvent& event : front_end_.TakeEvents()) {
      if (event.kind != estimator::FrontEndEvent::Kind::kInitialized) continue;
      const estimator::SolveResult& solve = event.init.solve;
      const double error_m = (solve.p_world_anchor - truth_.at(event.anchor_id).p_world_anchor).norm();
      ++record_.certified;
      if (detour_ && *detour_ == event.anchor_id) detour_.reset();
      if (error_m > r_.row.estimator.certificate.accuracy_m) ++record_.beyond_accuracy;
      record_.max_error_m = std::max(record_.max_error_m, error_m);
      usable_.push_back({event.anchor_id, t_s, solve.p_world_anchor, solve.bias_m, solve.covariance, false});
    }
  }

  // The offline baseline's waypoints, planned once; guided's and the oracle's detour when one is
  // due and a candidate is worth it.
  void Decide(double t_s) {
    const int dwell_epochs = static_cast<int>(std::ceil(ex_.dwell_s * rate_hz_));
    if (plans_ && body_.on_pattern() && t_s >= ex_.plan_after_s) {
      plans_ = false;
      std::vector<Eigen::Vector3d> route = PlanRoute(front_end_, body_.p_world_body(), ex_, space_, rate_hz_);
      record_.detours = static_cast<int>(route.size());
      body_.Visit(std::move(route), dwell_epochs);
    }
    if (body_.dwelling() && detours_ && !detour_) {
      body_.Leave();  // the detour's anchor is certified: the rest of the dwell would be idle
      next_decision_s_ = t_s;
    }
    if (detours_ && body_.free() && t_s >= next_decision_s_) {
      next_decision_s_ = t_s + ex_.decision_period_s;
      if (const std::optional<Detour> detour =
              NextDetour(front_end_, body_.p_world_body(), ex_, space_, rate_hz_, detours_of_, oracle_)) {
        body_.Visit({detour->p_world_candidate}, dwell_epochs);
        ++detours_of_[detour->anchor_id];
        detour_ = detour->anchor_id;
        ++record_.detours;
      }
    }
  }

  // Tag 0's flight through the navigation filter with the anchors certified, each from then on.
  void Navigate(const schema::NavigationConfig& navigation) {
    sim::RandomStream rng(r_.seed, static_cast<std::uint64_t>(r_.index), schema::kNavigationStream);
    nav::NavigationOutcome outcome =
        NavigateMethods(flown_, {{record_.policy, usable_}},
                        OptionsOf(navigation, r_.row.scenario.ranging.sigma_range_m), rng, 0, r_.index)
            .front()
            .outcome;
    record_.navigation_rmse_m = outcome.rmse_m;
    record_.navigation_error_by_bin_m = std::move(outcome.error_by_bin_m);
  }

  const Realization& r_;
  const schema::ExplorationConfig& ex_;
  const double rate_hz_;
  const double dt_s_;
  const bool navigated_;
  const std::map<int, schema::AnchorTruth> truth_;
  estimator::FrontEnd front_end_;
  sim::RangeDraws draws_;
  sim::TagPlacement placement_;
  const FreeSpace space_;
  Body body_;
  const bool detours_;
  bool plans_;
  const std::map<int, schema::AnchorTruth>* oracle_;
  ExplorationRecord record_;
  double next_decision_s_;
  std::map<int, int> detours_of_;  // detours flown for each anchor
  std::optional<int> detour_;      // the anchor of the detour flown now, until it is certified
  std::vector<Eigen::Vector3d> p_true_, p_reported_;
  std::vector<sim::SimRange> ranges_;
  Trajectory flown_;                      // navigated: tag 0's flight and ranges
  std::vector<nav::UsableAnchor> usable_;  // and the anchors certified
};

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
  const Realization r{row, seed, realization, anchors, pattern.p_world_tag};
  for (const std::string& policy : exploration.policies) {
    records.push_back(PolicyRun(r, exploration, components, policy, navigation.has_value()).Run(navigation));
    records.back().row = row_index;
  }
  return records;
}

UnitRecords<ExplorationRecord> ExplorationUnits(const schema::ExperimentConfig& config,
                                                const registry::Components& components) {
  const std::vector<schema::RowConfig> rows = schema::RowsOf(config);
  const int realizations = config.realizations;
  UnitRecords<ExplorationRecord> study;
  study.units = static_cast<int>(rows.size()) * realizations;
  study.compute = [rows, realizations, seed = config.seed, exploration = *config.exploration,
                   navigation = config.navigation, &components](int unit) {
    const int row = unit / realizations;
    return ExploreRealization(rows[static_cast<std::size_t>(row)], row, seed, unit % realizations, exploration,
                              navigation, components);
  };
  study.text = ExplorationUnitText;
  study.read = [realizations, policies = config.exploration->policies](const std::string& text,
                                                                       const engine::UnitPlace& place, int unit) {
    return ReadExplorationUnit(text, place, unit / realizations, unit % realizations, policies);
  };
  return study;
}

std::vector<ExplorationRecord> RunExploration(const schema::ExperimentConfig& config,
                                              const registry::Components& components, int threads,
                                              const RunControl& control, RecordJournal* journal) {
  CheckExploration(config, components);
  return RunUnitRecords(ExplorationUnits(config, components), threads, Shard{}, control, journal);
}

}  // namespace anchorbench::studies
