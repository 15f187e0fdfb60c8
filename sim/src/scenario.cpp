#include "anchorbench/sim/scenario.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

#include "anchorbench/sim/random_stream.hpp"
#include "anchorbench/sim/range_draws.hpp"

namespace anchorbench::sim {
namespace {

double DrawBias(const RangeModelOptions& o, RandomStream& rng) {
  return o.bias_distribution == BiasDistribution::kUniform ? rng.Uniform(o.bias_a_m, o.bias_b_m)
                                                           : rng.Normal(o.bias_a_m, o.bias_b_m);
}

// Each tag at its rigid offset, true and as reported, epoch by epoch.
void PlaceTags(const ScenarioOptions& options, std::uint64_t seed, std::uint64_t realization, Scenario& scenario) {
  TagPlacement placement(options, seed, realization);
  const std::size_t tags = options.tag_offsets_m.size();
  scenario.p_world_tag_true.assign(tags, {});
  scenario.p_world_tag_reported.assign(tags, {});
  std::vector<Eigen::Vector3d> p_true, p_reported;
  for (std::size_t k = 0; k < scenario.t_s.size(); ++k) {
    placement.Next(scenario.p_world_body[k], scenario.yaw_rad[k], &p_true, &p_reported);
    for (std::size_t tag = 0; tag < tags; ++tag) {
      scenario.p_world_tag_true[tag].push_back(p_true[tag]);
      scenario.p_world_tag_reported[tag].push_back(p_reported[tag]);
    }
  }
}

}  // namespace

std::vector<SimAnchor> DrawAnchors(const ScenarioOptions& options, std::uint64_t seed, std::uint64_t realization) {
  RandomStream layout(seed, realization, StreamId::kLayout);
  const std::vector<Eigen::Vector3d> positions = options.MakeEnvironment()->Anchors(layout);
  RandomStream bias_rng(seed, realization, StreamId::kBias);
  std::vector<SimAnchor> anchors;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    anchors.push_back({static_cast<int>(i), positions[i], DrawBias(options.ranging, bias_rng)});
  }
  return anchors;
}

Trajectory DrawBodyPath(const ScenarioOptions& options, const std::vector<SimAnchor>& anchors, std::uint64_t seed,
                          std::uint64_t realization) {
  RandomStream shape(seed, realization, StreamId::kTrajectory);
  TrajectoryOptions trajectory = options.trajectory;
  trajectory.kind = DrawTrajectoryKind(options.trajectory, shape);
  std::vector<Eigen::Vector3d> p_world_anchors;
  for (const SimAnchor& anchor : anchors) p_world_anchors.push_back(anchor.p_world_anchor);
  return options.MakeEnvironment()->Path(trajectory, p_world_anchors, shape);
}

std::vector<double> Headings(const std::vector<Eigen::Vector3d>& p_world_body) {
  const std::size_t epochs = p_world_body.size();
  std::vector<double> yaw_rad(epochs, 0.0);
  for (std::size_t k = 0; k < epochs; ++k) {
    const Eigen::Vector3d step = p_world_body[std::min(k + 1, epochs - 1)] - p_world_body[k > 0 ? k - 1 : 0];
    yaw_rad[k] = step.head<2>().norm() > 1e-9 ? std::atan2(step.y(), step.x()) : (k > 0 ? yaw_rad[k - 1] : 0.0);
  }
  return yaw_rad;
}

bool ScenarioOptions::IsValid(std::string* why) const {
  if (tag_offsets_m.empty() || tag_offsets_m.size() > static_cast<std::size_t>(kMaxTags) ||
      !std::all_of(tag_offsets_m.begin(), tag_offsets_m.end(), [](const Eigen::Vector3d& p) { return p.allFinite(); })) {
    if (why) *why = "tag_offsets_m must list 1 to 16 finite offsets [x, y, z]";
    return false;
  }
  if (!MakeEnvironment()->IsValid(trajectory, why) || !trajectory.IsValid(why) || !ranging.IsValid(why)) return false;
  const double tag_epochs = MaxEpochs() * static_cast<double>(tag_offsets_m.size());
  if (!(tag_epochs <= kMaxTagEpochs) || !(tag_epochs * NumAnchors() <= kMaxRangeSlots)) {
    if (why) {
      *why = "one realization would hold up to " + std::to_string(static_cast<long long>(std::min(tag_epochs, 1e18))) +
             " tag positions and " + std::to_string(static_cast<long long>(std::min(tag_epochs * NumAnchors(), 1e18))) +
             " range slots (epochs x tags x anchors); the limits are 1e7 and 2e7: shorten the run (length, speed, "
             "duration, rate) or use fewer tags or anchors";
    }
    return false;
  }
  return true;
}

double ScenarioOptions::MaxEpochs() const { return MakeEnvironment()->LongestRun_s(trajectory) * trajectory.rate_hz + 1.0; }

std::shared_ptr<const Environment> ScenarioOptions::MakeEnvironment() const {
  if (!custom_environment.empty()) {
    if (!custom) throw std::logic_error("environment '" + custom_environment + "' was never built (config::LoadConfig builds it)");
    return custom;
  }
  return environment == EnvironmentKind::kTunnel ? std::shared_ptr<const Environment>(MakeTunnel(tunnel))
                                                 : std::shared_ptr<const Environment>(MakeHall(hall));
}

std::string ScenarioOptions::EnvironmentName() const {
  return custom_environment.empty() ? std::string(ToString(environment)) : custom_environment;
}

Scenario GenerateScenario(const ScenarioOptions& options, std::uint64_t seed, std::uint64_t realization) {
  Scenario scenario;
  scenario.anchors = DrawAnchors(options, seed, realization);
  Trajectory trajectory = DrawBodyPath(options, scenario.anchors, seed, realization);
  scenario.t_s = std::move(trajectory.t_s);
  scenario.p_world_body = std::move(trajectory.p_world_tag);
  scenario.yaw_rad = Headings(scenario.p_world_body);
  PlaceTags(options, seed, realization, scenario);
  RangeDraws draws(options.ranging, seed, realization, scenario.p_world_tag_true.size(), scenario.anchors);
  std::vector<Eigen::Vector3d> p_world_tag_true(scenario.p_world_tag_true.size());
  for (std::size_t k = 0; k < scenario.t_s.size(); ++k) {
    for (std::size_t tag = 0; tag < p_world_tag_true.size(); ++tag) p_world_tag_true[tag] = scenario.p_world_tag_true[tag][k];
    draws.Epoch(k, scenario.t_s[k], p_world_tag_true, scenario.yaw_rad[k], &scenario.ranges);
  }
  return scenario;
}

}  // namespace anchorbench::sim
