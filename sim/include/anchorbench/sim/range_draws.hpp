#pragma once
// A realization's draws one epoch at a time: what GenerateScenario draws for a whole trajectory,
// and what a closed-loop run (studies/exploration.hpp) draws for positions it chooses as it goes.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/sim/random_stream.hpp"
#include "anchorbench/sim/range_model.hpp"

namespace anchorbench::sim {

struct ScenarioOptions;
struct SimAnchor;
struct SimRange;

// Each tag at its rigid offset from the body, true and as reported: one navigation error per
// epoch (sigma_position_m per axis), shared by the rigidly mounted tags.
class TagPlacement {
 public:
  TagPlacement(const ScenarioOptions& options, std::uint64_t seed, std::uint64_t realization);
  // The next epoch's tags for the body at p_world_body, heading yaw_rad (about z).
  void Next(const Eigen::Vector3d& p_world_body, double yaw_rad, std::vector<Eigen::Vector3d>* p_world_tag_true,
            std::vector<Eigen::Vector3d>* p_world_tag_reported);

 private:
  std::vector<Eigen::Vector3d> tag_offsets_m_;
  double sigma_position_m_;
  RandomStream position_rng_;
};

// The range stream of Eq. (1). One random stream per (tag, anchor) and noise source, so a link's
// noise does not depend on where the tag went before or which other anchors were in range.
class RangeDraws {
 public:
  // `tags` tags ranging to `anchors`; the radio biases (range_model.hpp) drawn here, none unless
  // configured. Keeps a reference to `model`.
  RangeDraws(const RangeModelOptions& model, std::uint64_t seed, std::uint64_t realization, std::size_t tags,
             const std::vector<SimAnchor>& anchors);
  ~RangeDraws();
  RangeDraws(RangeDraws&&) noexcept;

  // Appends epoch `epoch`'s ranges (tag, then anchor in the anchors' order) for the tags' true
  // positions and the body's heading; anchors beyond max_range_m or dropped give none.
  void Epoch(std::size_t epoch, double t_s, std::span<const Eigen::Vector3d> p_world_tag_true, double yaw_rad,
             std::vector<SimRange>* ranges);

 private:
  struct Links;
  std::unique_ptr<Links> links_;
};

}  // namespace anchorbench::sim
