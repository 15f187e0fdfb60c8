#include "anchorbench/sim/range_draws.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "anchorbench/sim/antenna_pattern.hpp"
#include "anchorbench/sim/random_stream.hpp"
#include "anchorbench/sim/scenario.hpp"

namespace anchorbench::sim {
namespace {

// (tag << 16 | anchor id) must fit a 24-bit sub-stream and stay distinct.
static_assert(kMaxAnchors <= (1 << 16) && ScenarioOptions::kMaxTags <= (1 << 8),
              "sub-stream keys (tag << 16 | anchor) must fit 24 bits");

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

}  // namespace

// One stream per (tag, anchor) and noise source; tag 0 keeps the sub-stream of a single-tag robot.
struct RangeDraws::Links {
  Links(const RangeModelOptions& model, std::uint64_t seed, std::uint64_t realization, std::size_t tags,
        const std::vector<SimAnchor>& anchors)
      : model(model), anchors(anchors), radio(model, seed, realization, tags, anchors) {
    for (std::size_t tag = 0; tag < tags; ++tag) {
      for (const SimAnchor& anchor : anchors) {
        const std::uint32_t substream = RadioBiases::Substream(tag, anchor);
        noise.emplace_back(seed, realization, StreamId::kRangeNoise, substream);
        outliers.emplace_back(model, RandomStream(seed, realization, StreamId::kOutlier, substream));
        dropout.emplace_back(seed, realization, StreamId::kDropout, substream);
      }
    }
  }

  const RangeModelOptions& model;
  std::vector<SimAnchor> anchors;
  RadioBiases radio;
  std::vector<RandomStream> noise, dropout;
  std::vector<OutlierProcess> outliers;
};

RangeDraws::RangeDraws(const RangeModelOptions& model, std::uint64_t seed, std::uint64_t realization, std::size_t tags,
                       const std::vector<SimAnchor>& anchors)
    : links_(std::make_unique<Links>(model, seed, realization, tags, anchors)) {}
RangeDraws::~RangeDraws() = default;
RangeDraws::RangeDraws(RangeDraws&&) noexcept = default;

void RangeDraws::Epoch(std::size_t epoch, double t_s, std::span<const Eigen::Vector3d> p_world_tag_true, double yaw_rad,
                       std::vector<SimRange>* ranges) {
  Links& l = *links_;
  const RangeModelOptions& model = l.model;
  const std::size_t anchors = l.anchors.size();
  for (std::size_t tag = 0; tag < p_world_tag_true.size(); ++tag) {
    for (const SimAnchor& anchor : l.anchors) {
      const std::size_t pair = tag * anchors + static_cast<std::size_t>(anchor.id);
      const Eigen::Vector3d p_anchor_tag = p_world_tag_true[tag] - anchor.p_world_anchor;
      const double distance_m = p_anchor_tag.norm();
      if (distance_m > model.max_range_m) continue;
      if (l.dropout[pair].Bernoulli(model.dropout_probability)) continue;
      const double outlier_m = l.outliers[pair].Next();
      const double radio_m = l.radio.any() ? l.radio.Of(tag, static_cast<std::size_t>(anchor.id), p_anchor_tag, yaw_rad) : 0.0;
      const double range_m = distance_m + anchor.bias_m + model.sigma_range_m * l.noise[pair].Normal() + outlier_m +
                             radio_m;  // Eq. (1) plus the outlier, if any, and the radio's biases
      // A ranging device never reports a negative distance.
      ranges->push_back({epoch, t_s, static_cast<int>(tag), anchor.id, std::max(range_m, 0.0), outlier_m != 0.0});
    }
  }
}

TagPlacement::TagPlacement(const ScenarioOptions& options, std::uint64_t seed, std::uint64_t realization)
    : tag_offsets_m_(options.tag_offsets_m),
      sigma_position_m_(options.ranging.sigma_position_m),
      position_rng_(seed, realization, StreamId::kPositionNoise) {}

void TagPlacement::Next(const Eigen::Vector3d& p_world_body, double yaw_rad, std::vector<Eigen::Vector3d>* p_world_tag_true,
                        std::vector<Eigen::Vector3d>* p_world_tag_reported) {
  // Drawn z, then y, then x, each in its own statement: the order of function arguments is
  // unspecified in C++ (GCC, which produced the committed results, evaluated them right to left).
  const double noise_z = position_rng_.Normal();
  const double noise_y = position_rng_.Normal();
  const double noise_x = position_rng_.Normal();
  const Eigen::Vector3d noise(noise_x, noise_y, noise_z);
  const Eigen::Matrix3d R_world_body = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  p_world_tag_true->resize(tag_offsets_m_.size());
  p_world_tag_reported->resize(tag_offsets_m_.size());
  for (std::size_t tag = 0; tag < tag_offsets_m_.size(); ++tag) {
    (*p_world_tag_true)[tag] = p_world_body + R_world_body * tag_offsets_m_[tag];
    (*p_world_tag_reported)[tag] = (*p_world_tag_true)[tag] + sigma_position_m_ * noise;
  }
}

}  // namespace anchorbench::sim
