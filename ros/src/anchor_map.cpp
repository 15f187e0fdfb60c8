#include "anchor_map.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

#include <Eigen/Eigenvalues>

#include <atomic>
#include <map>
#include <mutex>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/atomic_file.hpp"
#include "anchorbench/estimator/certified_trigger.hpp"
#include "anchorbench/estimator/guide.hpp"
#include "anchorbench/estimator/live_front_end.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/schema/experiment.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::ros_node {
namespace {

// The trigger the robot uses: the one named, else certified where the config lists it, else the
// first one that fires online (the fixed window only solves at the end of data).
std::string PublishedTrigger(const schema::ExperimentConfig& config, const std::string& named) {
  if (!named.empty()) return named;
  const std::vector<std::string>& triggers = config.estimator.triggers;
  if (std::find(triggers.begin(), triggers.end(), "certified") != triggers.end()) return "certified";
  for (const std::string& trigger : triggers) {
    if (trigger != schema::kFixedWindowTrigger) return trigger;
  }
  throw BadSetting("parameter ~trigger: the config's estimator.triggers list no trigger that fires online");
}

// Only the published trigger's chain: a robot pays for no other.
schema::ExperimentConfig WithOnlyTrigger(schema::ExperimentConfig config, const std::string& trigger) {
  if (trigger == schema::kFixedWindowTrigger) {
    throw BadSetting("parameter ~trigger: fixed_window solves only at the end of the data; name an online trigger");
  }
  config.estimator.triggers = {trigger};
  return config;
}

std::string WaitingFor(const std::optional<estimator::Judgement>& judgement) {
  if (!judgement) return "initialized";
  std::ostringstream text;  // (string + string here trips GCC 12's -Wrestrict false positive)
  text << judgement->blocked_by;
  if (!std::isnan(judgement->value)) text << ' ' << io::FormatNumber(judgement->value);
  if (!std::isnan(judgement->limit)) text << " (limit " << io::FormatNumber(judgement->limit) << ')';
  if (judgement->evidence_explained > 0.0) {  // how much worse the other fit is, and how much of that a pattern explains
    text << "; " << io::FormatNumber(judgement->evidence + judgement->evidence_explained)
         << " before what the model error could explain (" << io::FormatNumber(judgement->evidence_explained) << ')';
  }
  if (std::isinf(judgement->samples_needed)) text << "; more of the same path will not settle it";
  if (std::isfinite(judgement->samples_needed)) {
    text << "; settled at about " << static_cast<long long>(std::ceil(judgement->samples_needed)) << " samples";
  }
  return text.str();
}


AnchorState StateOf(int anchor_id, const estimator::InitEvent& event) {
  AnchorState state;
  state.anchor_id = anchor_id;
  state.initialized = true;
  state.p_world_anchor = event.solve.p_world_anchor;
  state.covariance = event.solve.covariance.topLeftCorner<3, 3>();
  state.bias_m = event.solve.bias_m;
  state.t_init_s = event.t_s;
  state.n_used = event.n_used;
  state.status = std::string(estimator::ToString(event.solve.status));
  state.samples = event.n_used;
  return state;
}

registry::Components BuiltinParts() {
  registry::Components components;
  registry::RegisterBuiltins(components);
  return components;
}

schema::ExperimentConfig Load(const std::string& path, const std::vector<std::string>& overrides,
                              const registry::Components& components) {
  try {
    return path.empty() ? config::LoadConfigText("{}", "defaults", overrides, components)
                        : config::LoadConfig(path, overrides, components);
  } catch (const schema::InputError& e) {
    throw BadSetting(e.what());
  }
}

// The config with only the trigger the robot uses, whose chains can be made (a trigger that needs
// the truth cannot).
schema::ExperimentConfig Prepared(const std::string& path, const std::vector<std::string>& overrides,
                                  const std::string& trigger, const registry::Components& components) {
  schema::ExperimentConfig config = Load(path, overrides, components);
  config = WithOnlyTrigger(config, PublishedTrigger(config, trigger));
  std::string why;
  if (!components.Check(config.estimator, &why)) throw BadSetting("parameter ~trigger: " + why);
  try {
    registry::MakeChains(components, 0, config.estimator, 0);
  } catch (const std::invalid_argument& e) {
    throw BadSetting("parameter ~trigger: " + std::string(e.what()));
  }
  return config;
}

}  // namespace

struct AnchorMap::Impl {
  Impl(const std::string& config_path, const std::vector<std::string>& overrides, const std::string& trigger)
      : components(BuiltinParts()),
        config(Prepared(config_path, overrides, trigger, components)),
        front_end(
            [this](int anchor_id) {
              return registry::MakeChains(components, anchor_id, config.estimator,
                                          config.seed + static_cast<std::uint64_t>(anchor_id));
            },
            estimator::FrontEndOptions{}) {}
  registry::Components components;
  schema::ExperimentConfig config;  // with only the published trigger: its chain is chain 0
  estimator::LiveFrontEnd front_end;
  mutable std::mutex mutex;          // guards initialized
  std::map<int, estimator::InitEvent> initialized;
  std::atomic<long> poses{0}, ranges{0}, malformed_ranges{0};
};

AnchorMap::AnchorMap(const std::string& config_path, const std::vector<std::string>& overrides,
                     const std::string& trigger)
    : impl_(std::make_unique<Impl>(config_path, overrides, trigger)) {}
AnchorMap::~AnchorMap() = default;

void AnchorMap::AddPose(double t_s, int tag_id, const Eigen::Vector3d& p_world_tag) {
  ++impl_->poses;
  impl_->front_end.AddPose(t_s, tag_id, p_world_tag);
}
void AnchorMap::AddRange(double t_s, int tag_id, int anchor_id, double range_m) {
  ++impl_->ranges;
  impl_->front_end.AddRange(t_s, tag_id, anchor_id, range_m);
}
void AnchorMap::CountMalformedRange() { ++impl_->malformed_ranges; }

InputCounts AnchorMap::Counts() const {
  const estimator::FrontEndCounters front = impl_->front_end.counters();
  InputCounts counts;
  counts.poses = impl_->poses;
  counts.ranges = impl_->ranges;
  counts.malformed_ranges = impl_->malformed_ranges;
  counts.samples = front.samples;
  counts.ranges_outside_poses = front.ranges_outside_poses;
  counts.ranges_without_pose = front.ranges_without_pose;
  counts.poses_ignored = front.poses_ignored;
  counts.ranges_beyond_max_anchors = front.ranges_beyond_max_anchors;
  return counts;
}
const std::string& AnchorMap::trigger() const { return impl_->config.estimator.triggers.front(); }
std::size_t AnchorMap::pending_solves() const { return impl_->front_end.pending_solves(); }

std::vector<AnchorState> AnchorMap::Step(std::size_t max_count, Clock::time_point deadline) {
  impl_->front_end.RunPendingSolves(max_count, deadline);
  std::vector<AnchorState> fresh;
  for (const estimator::FrontEndEvent& event : impl_->front_end.TakeEvents()) {
    if (event.kind != estimator::FrontEndEvent::Kind::kInitialized) continue;
    if (!estimator::Succeeded(event.init.solve.status)) continue;
    {
      std::lock_guard lock(impl_->mutex);
      impl_->initialized[event.anchor_id] = event.init;
    }
    fresh.push_back(StateOf(event.anchor_id, event.init));
  }
  return fresh;
}

std::vector<AnchorState> AnchorMap::States() const {
  std::vector<AnchorState> states = impl_->front_end.Inspect([](const estimator::FrontEnd& front_end) {
    std::vector<AnchorState> out;
    for (const int anchor_id : front_end.anchor_ids()) {
      const estimator::AnchorInitializer& chain = front_end.chains(anchor_id).front();
      AnchorState state;
      state.anchor_id = anchor_id;
      state.waiting_for = WaitingFor(chain.why_not());
      state.samples = static_cast<long>(chain.range_m().size());  // buffered: accepted, up to the cap
      out.push_back(state);
    }
    return out;
  });
  std::lock_guard lock(impl_->mutex);
  for (AnchorState& state : states) {
    if (const auto found = impl_->initialized.find(state.anchor_id); found != impl_->initialized.end()) {
      state = StateOf(state.anchor_id, found->second);
    }
  }
  return states;
}

std::vector<AnchorGuide> AnchorMap::Guide(double reach_m, int steps, std::size_t best, double range_rate_hz) const {
  estimator::GuideRequest request;
  request.reach_m = reach_m;
  request.steps = steps;
  request.best = best;
  request.range_rate_hz = range_rate_hz;
  const std::vector<estimator::AnchorGuidance> guided = impl_->front_end.Inspect(
      [&](const estimator::FrontEnd& front_end) { return estimator::Guide(front_end, request); });
  std::vector<AnchorGuide> out;
  for (const estimator::AnchorGuidance& g : guided) {
    AnchorGuide guide;
    guide.anchor_id = g.anchor_id;
    guide.blocked_by = std::string(g.blocked_by);
    guide.region_m = g.region_m;
    guide.accuracy_m = g.accuracy_m;
    for (const estimator::CandidateForecast& c : g.best) {
      guide.p_world_candidate.push_back(c.p_world_candidate);
      guide.samples_to_certify.push_back(c.samples_to_certify);
    }
    guide.seconds_to_certify = g.seconds_to_certify;
    out.push_back(std::move(guide));
  }
  return out;
}

std::vector<Eigen::Vector3d> WaypointsOf(const std::vector<AnchorGuide>& guides) {
  std::vector<const AnchorGuide*> closing;
  for (const AnchorGuide& guide : guides) {
    if (std::isfinite(guide.seconds_to_certify) && !guide.p_world_candidate.empty()) closing.push_back(&guide);
  }
  std::stable_sort(closing.begin(), closing.end(), [](const AnchorGuide* a, const AnchorGuide* b) {
    return a->seconds_to_certify < b->seconds_to_certify || (a->seconds_to_certify == b->seconds_to_certify &&
                                                             a->anchor_id < b->anchor_id);
  });
  std::vector<Eigen::Vector3d> waypoints;
  for (const AnchorGuide* guide : closing) waypoints.push_back(guide->p_world_candidate.front());
  return waypoints;
}

void AnchorMap::Reset() {
  impl_->front_end.ResetAll();
  std::lock_guard lock(impl_->mutex);
  impl_->initialized.clear();
}

bool AnchorMap::Reset(int anchor_id) {
  const bool known = impl_->front_end.ResetAnchor(anchor_id);
  std::lock_guard lock(impl_->mutex);
  impl_->initialized.erase(anchor_id);
  return known;
}

std::string AnchorsCsv(const std::vector<AnchorState>& anchors) {
  std::ostringstream out;
  out << "anchor_id,x,y,z,bias,t_init,n_used,var_x,var_y,var_z\n";
  for (const AnchorState& a : anchors) {
    if (!a.initialized) continue;
    out << a.anchor_id << ',' << io::FormatNumber(a.p_world_anchor.x()) << ',' << io::FormatNumber(a.p_world_anchor.y())
        << ',' << io::FormatNumber(a.p_world_anchor.z()) << ',' << io::FormatNumber(a.bias_m) << ','
        << io::FormatNumber(a.t_init_s) << ',' << a.n_used << ',' << io::FormatNumber(a.covariance(0, 0)) << ','
        << io::FormatNumber(a.covariance(1, 1)) << ',' << io::FormatNumber(a.covariance(2, 2)) << '\n';
  }
  return out.str();
}

std::string AnchorsYaml(const std::vector<AnchorState>& anchors, const std::string& frame_id) {
  std::ostringstream out;
  out << "frame_id: \"" << frame_id << "\"\nanchors:\n";
  for (const AnchorState& a : anchors) {
    if (!a.initialized) continue;
    out << "  - {id: " << a.anchor_id << ", position_m: [" << io::FormatNumber(a.p_world_anchor.x()) << ", "
        << io::FormatNumber(a.p_world_anchor.y()) << ", " << io::FormatNumber(a.p_world_anchor.z())
        << "], bias_m: " << io::FormatNumber(a.bias_m) << ", t_init_s: " << io::FormatNumber(a.t_init_s)
        << ", n_used: " << a.n_used << "}\n";
  }
  return out.str();
}

void SaveAnchors(const std::string& folder, const std::vector<AnchorState>& anchors, const std::string& frame_id) {
  std::filesystem::create_directories(folder);
  const std::pair<const char*, std::string> files[] = {{"anchors.csv", AnchorsCsv(anchors)},
                                                       {"anchors.yaml", AnchorsYaml(anchors, frame_id)}};
  for (const auto& [name, text] : files) {
    io::AtomicFile file(std::filesystem::path(folder) / name, /*overwrite=*/true);
    file.stream() << text;
    file.Commit();
  }
}

Ellipsoid EllipsoidOf(const Eigen::Matrix3d& covariance, double confidence) {
  Ellipsoid e;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(covariance);
  if (axes.info() != Eigen::Success || !covariance.allFinite()) return e;
  const double chi2 = estimator::ChiSquare3Quantile(confidence);
  for (int i = 0; i < 3; ++i) e.diameters_m(i) = 2.0 * std::sqrt(chi2 * std::max(axes.eigenvalues()(i), 0.0));
  Eigen::Matrix3d rotation = axes.eigenvectors();
  if (rotation.determinant() < 0) rotation.col(2) *= -1.0;  // a rotation, not a reflection
  e.orientation = Eigen::Quaterniond(rotation);
  return e;
}

std::optional<int> AnchorIdFromFrame(const std::string& frame_id) {
  std::size_t start = frame_id.size();
  while (start > 0 && std::isdigit(static_cast<unsigned char>(frame_id[start - 1]))) --start;
  if (start == frame_id.size() || frame_id.size() - start > 9) return std::nullopt;
  return std::stoi(frame_id.substr(start));
}

}  // namespace anchorbench::ros_node
