#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "anchorbench/estimator/enum_names.hpp"
#include "anchorbench/sim/environment.hpp"
#include "anchorbench/sim/random_stream.hpp"

namespace anchorbench::sim {

enum class TrajectoryKind {
  kRandom,    // smooth random 3D motion (lateral and vertical excursions)
  kStraight,  // ill-conditioned: straight line at constant height and lateral offset
  kPlanar,    // ill-conditioned: lateral weaving at (nearly) constant height
  kShort,     // ill-conditioned: random motion over a fraction of the environment only
  kApproach,  // hall only (ours): a hand-held approach at anchor 0 inside a narrow cone, then kRandom
};

inline constexpr estimator::EnumNames<TrajectoryKind, 5> kTrajectoryKindNames({
    {TrajectoryKind::kRandom, "random"}, {TrajectoryKind::kStraight, "straight"},
    {TrajectoryKind::kPlanar, "planar"}, {TrajectoryKind::kShort, "short"}, {TrajectoryKind::kApproach, "approach"}});
inline std::string_view ToString(TrajectoryKind value) { return kTrajectoryKindNames.Name(value); }
inline bool ParseTrajectoryKind(std::string_view name, TrajectoryKind* value) { return kTrajectoryKindNames.Parse(name, value); }

struct TrajectoryOptions {
  TrajectoryKind kind = TrajectoryKind::kRandom;
  // Monte Carlo mixes: each realization is drawn straight / planar / short with these
  // probabilities, and `kind` otherwise (the suboptimal trajectories among random ones of Table I).
  double fraction_straight = 0.0;
  double fraction_planar = 0.0;
  double fraction_short = 0.0;
  double rate_hz = 10.0;               // tag position (and range) sampling rate
  double speed_mps = 1.5;              // mean speed along the tunnel
  double speed_variation = 0.3;        // relative +- variation of the along-track speed
  double height_m = 2.0;               // mean tag height above the floor
  double lateral_excursion_m = 2.5;    // max lateral offset from the centre line
  double vertical_excursion_m = 1.5;   // max vertical offset from height_m (kRandom, kShort)
  // kPlanar: a small height wobble, uniform in [0, this] per realization (0: exactly planar), so a
  // mix of planar runs ranges from mirror-ambiguous to merely ill-conditioned.
  double planar_vertical_excursion_m = 0.0;
  double min_period_s = 8.0;           // periods of the smooth random excursions
  double max_period_s = 40.0;
  double short_fraction = 0.25;        // kShort: fraction of the length covered (tunnel: one stretch;
                                       // hall: the run wanders over that fraction of the length)
  double hall_duration_s = 300.0;      // hall trajectories: duration
  // kApproach: the tag walks at anchor 0 from approach_start_m to approach_end_m in
  // approach_duration_s, waving inside a cone of approach_cone_deg half-angle about the line from
  // the anchor into the hall; then it wanders as kRandom (a public recording's first seconds,
  // where range and bias trade off along the cone's axis: docs/method.md).
  double approach_start_m = 3.0;
  double approach_end_m = 1.3;
  double approach_cone_deg = 36.0;
  double approach_duration_s = 7.0;

  bool IsValid(std::string* why) const;
};

struct Trajectory {
  std::vector<double> t_s;
  std::vector<Eigen::Vector3d> p_world_tag;
};

// The kind of one realization: `kind`, or a suboptimal one with the fractions' probabilities.
TrajectoryKind DrawTrajectoryKind(const TrajectoryOptions& options, RandomStream& rng);

// From one end of the tunnel towards the other (or a stretch of it, kShort).
Trajectory TunnelTrajectory(const TunnelOptions& tunnel, const TrajectoryOptions& options, RandomStream& rng);
// Smooth wandering inside the hall, kept off the walls.
Trajectory HallTrajectory(const HallOptions& hall, const TrajectoryOptions& options, RandomStream& rng);
// kApproach: the approach at the anchor at p_world_anchor, then HallTrajectory's wandering.
Trajectory ApproachTrajectory(const HallOptions& hall, const TrajectoryOptions& options,
                              const Eigen::Vector3d& p_world_anchor, RandomStream& rng);

}  // namespace anchorbench::sim
