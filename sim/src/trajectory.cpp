#include "anchorbench/sim/trajectory.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace anchorbench::sim {
namespace {

constexpr double kWallClearance_m = 0.3;

// A smooth random signal in [-1, 1]: a normalized sum of three sinusoids with random periods,
// phases and amplitudes.
class SmoothSignal {
 public:
  SmoothSignal(RandomStream& rng, double min_period_s, double max_period_s) {
    double total = 0.0;
    for (Component& c : components_) {
      c.amplitude = rng.Uniform(0.5, 1.0);
      c.omega = 2.0 * std::numbers::pi / rng.Uniform(min_period_s, max_period_s);
      c.phase = rng.Uniform(0.0, 2.0 * std::numbers::pi);
      total += c.amplitude;
    }
    for (Component& c : components_) c.amplitude /= total;
  }

  double operator()(double t_s) const {
    double value = 0.0;
    for (const Component& c : components_) value += c.amplitude * std::sin(c.omega * t_s + c.phase);
    return value;
  }

 private:
  struct Component {
    double amplitude, omega, phase;
  };
  std::array<Component, 3> components_;
};

// Always one draw, so the rest of the trajectory stream does not depend on the kind.
double VerticalExcursion(const TrajectoryOptions& o, RandomStream& rng) {
  const double planar_wobble_m = rng.Uniform(0.0, o.planar_vertical_excursion_m);
  switch (o.kind) {
    case TrajectoryKind::kStraight: return 0.0;
    case TrajectoryKind::kPlanar: return planar_wobble_m;
    default: return o.vertical_excursion_m;
  }
}

}  // namespace

bool TrajectoryOptions::IsValid(std::string* why) const {
  auto fail = [why](const char* m) {
    if (why) *why = m;
    return false;
  };
  // Lengths up to 10 km, periods and durations up to 1e6 s (the epochs are bounded in ScenarioOptions).
  auto length = [](double v) { return v >= 0.0 && v <= 1e4; };
  if (!(rate_hz > 0.0 && rate_hz <= 1000.0)) return fail("rate_hz must be in (0, 1000]");
  if (!(speed_mps > 0.0 && speed_mps <= 1000.0)) return fail("speed_mps must be in (0, 1000]");
  if (!(speed_variation >= 0.0 && speed_variation < 1.0)) return fail("speed_variation must be in [0, 1)");
  if (!length(height_m)) return fail("height_m must be in [0, 1e4]");
  if (!length(lateral_excursion_m)) return fail("lateral_excursion_m must be in [0, 1e4]");
  if (!length(vertical_excursion_m)) return fail("vertical_excursion_m must be in [0, 1e4]");
  if (!length(planar_vertical_excursion_m)) return fail("planar_vertical_excursion_m must be in [0, 1e4]");
  if (!(min_period_s > 0.0 && min_period_s <= 1e6)) return fail("min_period_s must be in (0, 1e6]");
  if (!(max_period_s >= min_period_s && max_period_s <= 1e6)) return fail("max_period_s must be in [min_period_s, 1e6]");
  if (!(short_fraction > 0.0 && short_fraction <= 1.0)) return fail("short_fraction must be in (0, 1]");
  if (!(hall_duration_s > 0.0 && hall_duration_s <= 1e6)) return fail("hall_duration_s must be in (0, 1e6]");
  for (double fraction : {fraction_straight, fraction_planar, fraction_short}) {
    if (!(fraction >= 0.0 && fraction <= 1.0)) return fail("fraction_straight, fraction_planar and fraction_short must be in [0, 1]");
  }
  if (!(approach_end_m > 0.0 && approach_start_m >= approach_end_m && approach_start_m <= 100.0)) {
    return fail("approach_start_m must be >= approach_end_m > 0 (and <= 100)");
  }
  if (!(approach_cone_deg >= 0.0 && approach_cone_deg <= 90.0)) return fail("approach_cone_deg must be in [0, 90]");
  if (!(approach_duration_s > 0.0 && approach_duration_s <= 1e6)) return fail("approach_duration_s must be in (0, 1e6]");
  if (!(fraction_straight + fraction_planar + fraction_short <= 1.0)) {
    return fail("fraction_straight, fraction_planar and fraction_short must sum to <= 1");
  }
  return true;
}

TrajectoryKind DrawTrajectoryKind(const TrajectoryOptions& o, RandomStream& rng) {
  const double u = rng.Uniform();  // always one draw, so the rest of the stream does not shift
  if (u < o.fraction_straight) return TrajectoryKind::kStraight;
  if (u < o.fraction_straight + o.fraction_planar) return TrajectoryKind::kPlanar;
  if (u < o.fraction_straight + o.fraction_planar + o.fraction_short) return TrajectoryKind::kShort;
  return o.kind;
}

Trajectory TunnelTrajectory(const TunnelOptions& tunnel, const TrajectoryOptions& o, RandomStream& rng) {
  const SmoothSignal lateral(rng, o.min_period_s, o.max_period_s);
  const SmoothSignal vertical(rng, o.min_period_s, o.max_period_s);
  const SmoothSignal speed(rng, o.min_period_s, o.max_period_s);
  const double fraction = o.kind == TrajectoryKind::kShort ? o.short_fraction : 1.0;
  const double x_start = rng.Uniform(0.0, (1.0 - fraction) * tunnel.length_m);
  const double x_end = x_start + fraction * tunnel.length_m;
  const double y_offset = rng.Uniform(-o.lateral_excursion_m, o.lateral_excursion_m);  // kStraight
  const bool weaves = o.kind != TrajectoryKind::kStraight;
  const double climb_m = VerticalExcursion(o, rng);
  const double y_limit = std::max(0.0, 0.5 * tunnel.width_m - kWallClearance_m);
  const double z_low = std::min(kWallClearance_m, tunnel.height_m);
  const double z_high = std::max(z_low, tunnel.height_m - kWallClearance_m);

  Trajectory trajectory;
  const double dt = 1.0 / o.rate_hz;
  double x = x_start;
  for (long k = 0; x <= x_end; ++k) {
    const double t = k * dt;
    const double y = weaves ? o.lateral_excursion_m * lateral(t) : y_offset;
    const double z = o.height_m + climb_m * vertical(t);
    trajectory.t_s.push_back(t);
    trajectory.p_world_tag.emplace_back(x, std::clamp(y, -y_limit, y_limit), std::clamp(z, z_low, z_high));
    x += o.speed_mps * (1.0 + o.speed_variation * speed(t)) * dt;
  }
  return trajectory;
}

Trajectory HallTrajectory(const HallOptions& hall, const TrajectoryOptions& o, RandomStream& rng) {
  const SmoothSignal along(rng, o.min_period_s, o.max_period_s);
  const SmoothSignal across(rng, o.min_period_s, o.max_period_s);
  const SmoothSignal vertical(rng, o.min_period_s, o.max_period_s);
  double half_x = std::max(0.0, 0.5 * hall.length_m - kWallClearance_m);
  const double half_y = std::max(0.0, 0.5 * hall.width_m - kWallClearance_m);
  const double duration_s = o.hall_duration_s;
  // kShort: a partial run, wandering over a random stretch of short_fraction of the hall's length
  // (drawn for every kind, so the rest of the stream does not depend on the kind).
  const double center_u = rng.Uniform(-1.0, 1.0);
  const double center_x = o.kind == TrajectoryKind::kShort ? center_u * (1.0 - o.short_fraction) * half_x : 0.0;
  if (o.kind == TrajectoryKind::kShort) half_x *= o.short_fraction;
  const double z_low = std::min(kWallClearance_m, hall.height_m);
  const double z_high = std::max(z_low, hall.height_m - kWallClearance_m);
  const double climb_m = VerticalExcursion(o, rng);
  // kStraight: one pass along the hall's long axis at a random lateral offset.
  const double y_offset = rng.Uniform(-half_y, half_y);

  Trajectory trajectory;
  const double dt = 1.0 / o.rate_hz;
  for (long k = 0; k * dt <= duration_s; ++k) {
    const double t = k * dt;
    Eigen::Vector3d p;
    if (o.kind == TrajectoryKind::kStraight) {
      p.x() = -half_x + 2.0 * half_x * t / duration_s;
      p.y() = y_offset;
    } else {
      p.x() = center_x + half_x * along(t);
      p.y() = half_y * across(t);
    }
    p.x() += 0.5 * hall.length_m;
    p.y() += 0.5 * hall.width_m;
    p.z() = std::clamp(o.height_m + climb_m * vertical(t), z_low, z_high);
    trajectory.t_s.push_back(t);
    trajectory.p_world_tag.push_back(p);
  }
  return trajectory;
}

Trajectory ApproachTrajectory(const HallOptions& hall, const TrajectoryOptions& o, const Eigen::Vector3d& p_world_anchor,
                              RandomStream& rng) {
  TrajectoryOptions wander = o;
  wander.kind = TrajectoryKind::kRandom;
  Trajectory trajectory = HallTrajectory(hall, wander, rng);
  // The cone's axis: from the anchor towards the hall's centre at the tag's height.
  const Eigen::Vector3d centre(0.5 * hall.length_m, 0.5 * hall.width_m, o.height_m);
  Eigen::Vector3d axis = centre - p_world_anchor;
  if (!(axis.norm() > 1e-9)) axis = Eigen::Vector3d::UnitX();
  axis.normalize();
  const Eigen::Vector3d side = axis.unitOrthogonal();
  const Eigen::Vector3d up = axis.cross(side);
  const double half_rad = o.approach_cone_deg * std::numbers::pi / 180.0;
  const double wave_period_s = rng.Uniform(1.5, 3.0), turn_period_s = rng.Uniform(1.5, 3.0);
  const double wave_phase = rng.Uniform(0.0, 2.0 * std::numbers::pi), turn_phase = rng.Uniform(0.0, 2.0 * std::numbers::pi);
  constexpr double kBlend_s = 4.0;  // from the approach's end into the wandering
  Eigen::Vector3d p_end = p_world_anchor;
  for (std::size_t k = 0; k < trajectory.t_s.size(); ++k) {
    const double t = trajectory.t_s[k];
    if (t <= o.approach_duration_s) {
      const double distance_m = o.approach_start_m + (o.approach_end_m - o.approach_start_m) * t / o.approach_duration_s;
      // The angle off the axis fills the cone (sqrt of a smooth [0, 1] signal), the turn goes round.
      const double off_rad = half_rad * std::sqrt(0.5 + 0.5 * std::sin(2.0 * std::numbers::pi * t / wave_period_s + wave_phase));
      const double turn_rad = 2.0 * std::numbers::pi * t / turn_period_s + turn_phase;
      const Eigen::Vector3d unit =
          std::cos(off_rad) * axis + std::sin(off_rad) * (std::cos(turn_rad) * side + std::sin(turn_rad) * up);
      p_end = trajectory.p_world_tag[k] = p_world_anchor + distance_m * unit;
    } else if (t < o.approach_duration_s + kBlend_s) {
      const double w = (t - o.approach_duration_s) / kBlend_s;
      trajectory.p_world_tag[k] = (1.0 - w) * p_end + w * trajectory.p_world_tag[k];
    }
  }
  return trajectory;
}

}  // namespace anchorbench::sim
