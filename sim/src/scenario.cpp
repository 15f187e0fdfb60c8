#include "anchorbench/sim/scenario.hpp"

#include <algorithm>

#include "anchorbench/sim/random_stream.hpp"

namespace anchorbench::sim {
namespace {

double DrawBias(const RangeModelOptions& o, RandomStream& rng) {
  return o.bias_distribution == BiasDistribution::kUniform ? rng.Uniform(o.bias_a_m, o.bias_b_m)
                                                           : rng.Normal(o.bias_a_m, o.bias_b_m);
}

double DrawOutlier(const RangeModelOptions& o, RandomStream& rng) {
  const double magnitude = rng.Uniform(o.outlier_min_m, o.outlier_max_m);
  const double sign = rng.Uniform() < 0.5 ? -1.0 : 1.0;  // drawn for both kinds: same stream use
  return o.outlier_kind == OutlierKind::kPositive ? magnitude : sign * magnitude;
}

// Outlier episodes of one anchor, a two-state Markov chain over its ranges: an episode ends
// with probability b = 1/L per range (mean length L) and starts with a = p b / (1 - p), so the
// stationary fraction of outlier ranges is a / (a + b) = p. One offset holds for a whole episode.
class OutlierProcess {
 public:
  OutlierProcess(const RangeModelOptions& o, RandomStream rng)
      : options_(o),
        rng_(rng),
        end_probability_(1.0 / o.outlier_burst_length),
        start_probability_(o.outlier_probability >= 1.0
                               ? 1.0
                               : o.outlier_probability * end_probability_ / (1.0 - o.outlier_probability)) {}

  // The outlier offset of the next range, 0 if it is not an outlier.
  double Next() {
    const double u = rng_.Uniform();
    if (offset_m_ != 0.0) {
      if (u < end_probability_) offset_m_ = 0.0;  // the episode ends on a clean range
    } else if (u < start_probability_) {
      offset_m_ = DrawOutlier(options_, rng_);
    }
    return offset_m_;
  }

 private:
  const RangeModelOptions& options_;
  RandomStream rng_;
  double end_probability_;
  double start_probability_;
  double offset_m_ = 0.0;
};

}  // namespace

std::string_view ToString(EnvironmentKind kind) { return kind == EnvironmentKind::kTunnel ? "tunnel" : "hall"; }

bool ParseEnvironmentKind(std::string_view name, EnvironmentKind* kind) {
  if (name == "tunnel") *kind = EnvironmentKind::kTunnel;
  else if (name == "hall") *kind = EnvironmentKind::kHall;
  else return false;
  return true;
}

bool ScenarioOptions::IsValid(std::string* why) const {
  const bool environment_ok = environment == EnvironmentKind::kTunnel ? tunnel.IsValid(why) : hall.IsValid(why);
  return environment_ok && trajectory.IsValid(why) && ranging.IsValid(why);
}

Scenario GenerateScenario(const ScenarioOptions& options, std::uint64_t seed, std::uint64_t realization) {
  Scenario scenario;
  RandomStream layout(seed, realization, StreamId::kLayout);
  RandomStream shape(seed, realization, StreamId::kTrajectory);
  const bool tunnel = options.environment == EnvironmentKind::kTunnel;
  const std::vector<Eigen::Vector3d> positions =
      tunnel ? TunnelAnchors(options.tunnel, layout) : HallAnchors(options.hall, layout);
  TrajectoryOptions trajectory_options = options.trajectory;
  trajectory_options.kind = DrawTrajectoryKind(options.trajectory, shape);
  scenario.trajectory_kind = trajectory_options.kind;
  Trajectory trajectory = tunnel ? TunnelTrajectory(options.tunnel, trajectory_options, shape)
                                 : HallTrajectory(options.hall, trajectory_options, shape);

  const RangeModelOptions& model = options.ranging;
  RandomStream bias_rng(seed, realization, StreamId::kBias);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    scenario.anchors.push_back({static_cast<int>(i), positions[i], DrawBias(model, bias_rng)});
  }

  RandomStream position_rng(seed, realization, StreamId::kPositionNoise);
  scenario.t_s = std::move(trajectory.t_s);
  scenario.p_world_tag_true = std::move(trajectory.p_world_tag);
  scenario.p_world_tag_reported.reserve(scenario.p_world_tag_true.size());
  for (const Eigen::Vector3d& p : scenario.p_world_tag_true) {
    const Eigen::Vector3d noise(position_rng.Normal(), position_rng.Normal(), position_rng.Normal());
    scenario.p_world_tag_reported.push_back(p + model.sigma_position_m * noise);
  }

  // One stream per anchor and noise source, so an anchor's noise does not depend on which other
  // anchors happen to be in range.
  std::vector<RandomStream> noise_rng, dropout_rng;
  std::vector<OutlierProcess> outliers;
  for (const SimAnchor& anchor : scenario.anchors) {
    const auto sub = static_cast<std::uint32_t>(anchor.id);
    noise_rng.emplace_back(seed, realization, StreamId::kRangeNoise, sub);
    outliers.emplace_back(model, RandomStream(seed, realization, StreamId::kOutlier, sub));
    dropout_rng.emplace_back(seed, realization, StreamId::kDropout, sub);
  }
  for (std::size_t k = 0; k < scenario.t_s.size(); ++k) {
    for (const SimAnchor& anchor : scenario.anchors) {
      const double distance_m = (scenario.p_world_tag_true[k] - anchor.p_world_anchor).norm();
      if (distance_m > model.max_range_m) continue;
      if (dropout_rng[anchor.id].Bernoulli(model.dropout_probability)) continue;
      const double outlier_m = outliers[anchor.id].Next();
      const double range_m = distance_m + anchor.bias_m + model.sigma_range_m * noise_rng[anchor.id].Normal() +
                             outlier_m;  // Eq. (1) plus the outlier, if any
      const bool outlier = outlier_m != 0.0;
      // A ranging device never reports a negative distance.
      scenario.ranges.push_back({scenario.t_s[k], 0, anchor.id, std::max(range_m, 0.0), outlier});
    }
  }
  return scenario;
}

}  // namespace anchorbench::sim
