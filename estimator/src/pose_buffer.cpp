#include "anchorbench/estimator/pose_buffer.hpp"

#include <algorithm>
#include <cmath>

namespace anchorbench::estimator {

bool PoseBuffer::Add(int tag_id, double t_s, const Eigen::Vector3d& p_world_tag) {
  if (!std::isfinite(t_s) || !p_world_tag.allFinite()) return false;
  std::deque<Pose>& track = tracks_[tag_id];
  if (!track.empty() && !(t_s > track.back().first)) return false;
  track.emplace_back(t_s, p_world_tag);
  while (track.size() > 2 && track.front().first < t_s - options_.history_s) track.pop_front();
  return true;
}

PoseBuffer::Lookup PoseBuffer::At(int tag_id, double t_s, Eigen::Vector3d* p_world_tag) const {
  const auto found = tracks_.find(tag_id);
  if (found == tracks_.end() || found->second.empty() || t_s > found->second.back().first) return Lookup::kNotYet;
  const std::deque<Pose>& track = found->second;
  if (t_s < track.front().first) return Lookup::kOutside;
  const auto after = std::upper_bound(track.begin(), track.end(), t_s,
                                      [](double t, const Pose& pose) { return t < pose.first; });
  if (after == track.end()) {  // exactly the newest pose
    *p_world_tag = track.back().second;
    return Lookup::kFound;
  }
  const Pose& before = *(after - 1);
  const double fraction = (t_s - before.first) / (after->first - before.first);
  *p_world_tag = before.second + fraction * (after->second - before.second);
  return Lookup::kFound;
}

std::optional<double> PoseBuffer::newest_t_s(int tag_id) const {
  const auto found = tracks_.find(tag_id);
  if (found == tracks_.end() || found->second.empty()) return std::nullopt;
  return found->second.back().first;
}

}  // namespace anchorbench::estimator
