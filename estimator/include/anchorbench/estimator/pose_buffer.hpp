#pragma once

#include <deque>
#include <map>
#include <optional>
#include <utility>

#include <Eigen/Core>

namespace anchorbench::estimator {

struct PoseBufferOptions {
  // Poses older than their tag's newest by more than this are forgotten (the two newest are
  // always kept). It must cover how late a range may be handed over after its tag's poses: the
  // front end's max_wait_s plus the longest gap between two poses.
  double history_s = 30.0;
};

// Tag positions as a navigation stack reports them, per tag, in increasing time, interpolated
// linearly at range times. Bounded: a sliding window of history_s per tag.
class PoseBuffer {
 public:
  enum class Lookup {
    kFound,        // interpolated (or exactly a pose)
    kNotYet,       // t is after the tag's newest pose (or the tag has none yet): a later pose may come
    kOutside,      // t is before the oldest pose kept: never extrapolated
  };

  explicit PoseBuffer(const PoseBufferOptions& options = {}) : options_(options) {}

  // False (and ignored) if the time does not increase for the tag or a value is not finite.
  bool Add(int tag_id, double t_s, const Eigen::Vector3d& p_world_tag);
  Lookup At(int tag_id, double t_s, Eigen::Vector3d* p_world_tag) const;
  std::optional<double> newest_t_s(int tag_id) const;

 private:
  using Pose = std::pair<double, Eigen::Vector3d>;
  PoseBufferOptions options_;
  std::map<int, std::deque<Pose>> tracks_;
};

}  // namespace anchorbench::estimator
