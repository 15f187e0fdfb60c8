#include "anchorbench/sim/scenario.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "anchorbench/sim/antenna_pattern.hpp"
#include "anchorbench/sim/random_stream.hpp"

namespace anchorbench::sim {
namespace {

// (tag << 16 | anchor id) must fit a 24-bit sub-stream and stay distinct.
static_assert(kMaxAnchors <= (1 << 16) && ScenarioOptions::kMaxTags <= (1 << 8),
              "sub-stream keys (tag << 16 | anchor) must fit 24 bits");

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

std::vector<SimAnchor> DrawAnchors(const ScenarioOptions& options, std::uint64_t seed, std::uint64_t realization) {
  RandomStream layout(seed, realization, StreamId::kLayout);
  const std::vector<Eigen::Vector3d> positions = options.environment == EnvironmentKind::kTunnel
                                                     ? TunnelAnchors(options.tunnel, layout)
                                                     : HallAnchors(options.hall, layout);
  RandomStream bias_rng(seed, realization, StreamId::kBias);
  std::vector<SimAnchor> anchors;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    anchors.push_back({static_cast<int>(i), positions[i], DrawBias(options.ranging, bias_rng)});
  }
  return anchors;
}

// The body's path, its kind drawn for this realization (Table I's mix of suboptimal runs).
Trajectory DrawTrajectory(const ScenarioOptions& options, const std::vector<SimAnchor>& anchors, std::uint64_t seed,
                          std::uint64_t realization) {
  RandomStream shape(seed, realization, StreamId::kTrajectory);
  TrajectoryOptions trajectory = options.trajectory;
  trajectory.kind = DrawTrajectoryKind(options.trajectory, shape);
  if (options.environment == EnvironmentKind::kTunnel) return TunnelTrajectory(options.tunnel, trajectory, shape);
  if (trajectory.kind == TrajectoryKind::kApproach) {
    return ApproachTrajectory(options.hall, trajectory, anchors.front().p_world_anchor, shape);
  }
  return HallTrajectory(options.hall, trajectory, shape);
}

// Heading along the direction of travel (central differences; kept while standing still).
std::vector<double> Headings(const std::vector<Eigen::Vector3d>& p_world_body) {
  const std::size_t epochs = p_world_body.size();
  std::vector<double> yaw_rad(epochs, 0.0);
  for (std::size_t k = 0; k < epochs; ++k) {
    const Eigen::Vector3d step = p_world_body[std::min(k + 1, epochs - 1)] - p_world_body[k > 0 ? k - 1 : 0];
    yaw_rad[k] = step.head<2>().norm() > 1e-9 ? std::atan2(step.y(), step.x()) : (k > 0 ? yaw_rad[k - 1] : 0.0);
  }
  return yaw_rad;
}

// Each tag at its rigid offset, true and as reported: one navigation error per epoch, shared.
void PlaceTags(const ScenarioOptions& options, std::uint64_t seed, std::uint64_t realization, Scenario& scenario) {
  RandomStream position_rng(seed, realization, StreamId::kPositionNoise);
  const std::size_t tags = options.tag_offsets_m.size();
  scenario.p_world_tag_true.assign(tags, {});
  scenario.p_world_tag_reported.assign(tags, {});
  for (std::size_t k = 0; k < scenario.t_s.size(); ++k) {
    // Drawn z, then y, then x, each in its own statement: the order of function arguments is
    // unspecified in C++ (GCC, which produced the committed results, evaluated them right to left).
    const double noise_z = position_rng.Normal();
    const double noise_y = position_rng.Normal();
    const double noise_x = position_rng.Normal();
    const Eigen::Vector3d noise(noise_x, noise_y, noise_z);
    const Eigen::Matrix3d R_world_body =
        Eigen::AngleAxisd(scenario.yaw_rad[k], Eigen::Vector3d::UnitZ()).toRotationMatrix();
    for (std::size_t tag = 0; tag < tags; ++tag) {
      const Eigen::Vector3d p_true = scenario.p_world_body[k] + R_world_body * options.tag_offsets_m[tag];
      scenario.p_world_tag_true[tag].push_back(p_true);
      scenario.p_world_tag_reported[tag].push_back(p_true + options.ranging.sigma_position_m * noise);
    }
  }
}

// The range stream of Eq. (1), epoch by epoch, tag by tag, anchor by anchor. One stream per
// (tag, anchor) and noise source, so a pair's noise does not depend on which other anchors happen
// to be in range; tag 0 keeps the sub-stream of a single-tag robot.
// What Eq. (1) leaves out (range_model.hpp), for every link; all zero, and nothing drawn, unless
// configured.
class RadioBiases {
 public:
  RadioBiases(const RangeModelOptions& model, std::uint64_t seed, std::uint64_t realization, std::size_t tags,
              const std::vector<SimAnchor>& anchors)
      : anchors_(anchors.size()),
        any_(model.antenna_bias_m > 0.0 || model.tag_antenna_bias_m > 0.0 || model.link_offset_m > 0.0 ||
             model.range_scale_sigma > 0.0) {
    for (const SimAnchor& anchor : anchors) {
      RandomStream pattern(seed, realization, StreamId::kAntennaPattern, static_cast<std::uint32_t>(anchor.id));
      anchor_pattern_.push_back(model.antenna_bias_m > 0.0 ? AntennaPattern(model.antenna_bias_m, pattern)
                                                           : AntennaPattern());
      RandomStream scale(seed, realization, StreamId::kRangeScale, static_cast<std::uint32_t>(anchor.id));
      scale_.push_back(model.range_scale_sigma > 0.0 ? model.range_scale_sigma * scale.Normal() : 0.0);
    }
    for (std::size_t tag = 0; tag < tags; ++tag) {
      RandomStream pattern(seed, realization, StreamId::kAntennaPattern, static_cast<std::uint32_t>(1u << 16 | tag));
      tag_pattern_.push_back(model.tag_antenna_bias_m > 0.0 ? AntennaPattern(model.tag_antenna_bias_m, pattern)
                                                            : AntennaPattern());
      for (const SimAnchor& anchor : anchors) {
        RandomStream offset(seed, realization, StreamId::kLinkOffset, Substream(tag, anchor));
        link_offset_m_.push_back(model.link_offset_m > 0.0 ? model.link_offset_m * offset.Normal() : 0.0);
      }
    }
  }

  static std::uint32_t Substream(std::size_t tag, const SimAnchor& anchor) {
    return static_cast<std::uint32_t>((tag << 16) | static_cast<std::uint32_t>(anchor.id));
  }

  bool any() const { return any_; }  // else Of() is 0 for every link: the paper's Eq. (1)

  // The bias of one range: the anchor sees the tag along u_anchor_tag, the tag (yawed body) the anchor.
  double Of(std::size_t tag, std::size_t anchor, const Eigen::Vector3d& p_anchor_tag, double yaw_rad) const {
    const double distance_m = p_anchor_tag.norm();
    if (!(distance_m > 0.0)) return 0.0;
    const Eigen::Vector3d u_anchor_tag = p_anchor_tag / distance_m;
    const Eigen::Vector3d u_body = Eigen::AngleAxisd(-yaw_rad, Eigen::Vector3d::UnitZ()) * (-u_anchor_tag);
    return scale_[anchor] * distance_m + anchor_pattern_[anchor](u_anchor_tag) + tag_pattern_[tag](u_body) +
           link_offset_m_[tag * anchors_ + anchor];
  }

 private:
  std::size_t anchors_;
  bool any_;
  std::vector<AntennaPattern> anchor_pattern_, tag_pattern_;
  std::vector<double> scale_, link_offset_m_;
};

std::vector<SimRange> DrawRanges(const RangeModelOptions& model, std::uint64_t seed, std::uint64_t realization,
                                 const Scenario& scenario) {
  const std::size_t tags = scenario.p_world_tag_true.size();
  const auto substream = [](std::size_t tag, const SimAnchor& anchor) { return RadioBiases::Substream(tag, anchor); };
  const RadioBiases radio(model, seed, realization, tags, scenario.anchors);
  std::vector<RandomStream> noise_rng, dropout_rng;
  std::vector<OutlierProcess> outliers;
  for (std::size_t tag = 0; tag < tags; ++tag) {
    for (const SimAnchor& anchor : scenario.anchors) {
      noise_rng.emplace_back(seed, realization, StreamId::kRangeNoise, substream(tag, anchor));
      outliers.emplace_back(model, RandomStream(seed, realization, StreamId::kOutlier, substream(tag, anchor)));
      dropout_rng.emplace_back(seed, realization, StreamId::kDropout, substream(tag, anchor));
    }
  }
  std::vector<SimRange> ranges;
  const std::size_t anchors = scenario.anchors.size();
  for (std::size_t k = 0; k < scenario.t_s.size(); ++k) {
    for (std::size_t tag = 0; tag < tags; ++tag) {
      for (const SimAnchor& anchor : scenario.anchors) {
        const std::size_t pair = tag * anchors + static_cast<std::size_t>(anchor.id);
        const double distance_m = (scenario.p_world_tag_true[tag][k] - anchor.p_world_anchor).norm();
        if (distance_m > model.max_range_m) continue;
        if (dropout_rng[pair].Bernoulli(model.dropout_probability)) continue;
        const double outlier_m = outliers[pair].Next();
        const Eigen::Vector3d p_anchor_tag = scenario.p_world_tag_true[tag][k] - anchor.p_world_anchor;
        const double radio_m =
            radio.any() ? radio.Of(tag, static_cast<std::size_t>(anchor.id), p_anchor_tag, scenario.yaw_rad[k]) : 0.0;
        const double range_m = distance_m + anchor.bias_m + model.sigma_range_m * noise_rng[pair].Normal() +
                               outlier_m + radio_m;  // Eq. (1) plus the outlier, if any, and the radio's biases
        // A ranging device never reports a negative distance.
        ranges.push_back({k, scenario.t_s[k], static_cast<int>(tag), anchor.id, std::max(range_m, 0.0), outlier_m != 0.0});
      }
    }
  }
  return ranges;
}

}  // namespace

bool ScenarioOptions::IsValid(std::string* why) const {
  if (tag_offsets_m.empty() || tag_offsets_m.size() > static_cast<std::size_t>(kMaxTags) ||
      !std::all_of(tag_offsets_m.begin(), tag_offsets_m.end(), [](const Eigen::Vector3d& p) { return p.allFinite(); })) {
    if (why) *why = "tag_offsets_m must list 1 to 16 finite offsets [x, y, z]";
    return false;
  }
  if (environment == EnvironmentKind::kTunnel && trajectory.kind == TrajectoryKind::kApproach) {
    if (why) *why = "trajectory.kind approach is a hall trajectory (the tunnel has none)";
    return false;
  }
  const bool environment_ok = environment == EnvironmentKind::kTunnel ? tunnel.IsValid(why) : hall.IsValid(why);
  if (!environment_ok || !trajectory.IsValid(why) || !ranging.IsValid(why)) return false;
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

double ScenarioOptions::MaxEpochs() const {
  const double duration_s = environment == EnvironmentKind::kTunnel
                                ? tunnel.length_m / (trajectory.speed_mps * (1.0 - trajectory.speed_variation))
                                : trajectory.hall_duration_s;
  return duration_s * trajectory.rate_hz + 1.0;
}

Scenario GenerateScenario(const ScenarioOptions& options, std::uint64_t seed, std::uint64_t realization) {
  Scenario scenario;
  scenario.anchors = DrawAnchors(options, seed, realization);
  Trajectory trajectory = DrawTrajectory(options, scenario.anchors, seed, realization);
  scenario.t_s = std::move(trajectory.t_s);
  scenario.p_world_body = std::move(trajectory.p_world_tag);
  scenario.yaw_rad = Headings(scenario.p_world_body);
  PlaceTags(options, seed, realization, scenario);
  scenario.ranges = DrawRanges(options.ranging, seed, realization, scenario);
  return scenario;
}

}  // namespace anchorbench::sim
