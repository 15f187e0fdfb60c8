#include "anchorbench/io/log_policy.hpp"

#include <stdexcept>
#include <string>

namespace anchorbench::io {

LogPolicy::RepeatedPoses RepeatedPosesFromName(std::string_view name) {
  if (name == "error") return LogPolicy::RepeatedPoses::kError;
  if (name == "first") return LogPolicy::RepeatedPoses::kFirst;
  if (name == "average") return LogPolicy::RepeatedPoses::kAverage;
  throw std::invalid_argument("'" + std::string(name) + "' is not one of error, first, average");
}

LogPolicy::OutOfOrder OutOfOrderFromName(std::string_view name) {
  if (name == "error") return LogPolicy::OutOfOrder::kError;
  if (name == "drop") return LogPolicy::OutOfOrder::kDrop;
  if (name == "sort") return LogPolicy::OutOfOrder::kSort;
  throw std::invalid_argument("'" + std::string(name) + "' is not one of error, drop, sort");
}

const char* NameOf(LogPolicy::RepeatedPoses policy) {
  switch (policy) {
    case LogPolicy::RepeatedPoses::kError: return "error";
    case LogPolicy::RepeatedPoses::kFirst: return "first";
    case LogPolicy::RepeatedPoses::kAverage: return "average";
  }
  return "?";
}

const char* NameOf(LogPolicy::OutOfOrder policy) {
  switch (policy) {
    case LogPolicy::OutOfOrder::kError: return "error";
    case LogPolicy::OutOfOrder::kDrop: return "drop";
    case LogPolicy::OutOfOrder::kSort: return "sort";
  }
  return "?";
}

const char* NameOf(Drop reason) {
  switch (reason) {
    case Drop::kRangeNotPositive: return "range_not_positive";
    case Drop::kRangeNotFinite: return "range_not_finite";
    case Drop::kRangeBeyondMax: return "range_beyond_max";
    case Drop::kDuplicateRange: return "duplicate_range";
    case Drop::kLateRange: return "late_range";
    case Drop::kOutsidePoses: return "outside_poses";
    case Drop::kNoPoseInTime: return "no_pose_in_time";
    case Drop::kTooManyAnchors: return "too_many_anchors";
    case Drop::kPoseNotFinite: return "pose_not_finite";
    case Drop::kRepeatedPose: return "repeated_pose";
    case Drop::kConflictingPose: return "conflicting_pose";
    case Drop::kAveragedPose: return "averaged_pose";
    case Drop::kLatePose: return "late_pose";
    case Drop::kPoseJump: return "pose_jump";
  }
  return "?";
}

bool IsPoseDrop(Drop reason) { return reason >= Drop::kPoseNotFinite; }

void LogDrops::Count(Drop reason, int id, const std::string& source, int line) {
  DropTally& tally = (IsPoseDrop(reason) ? poses_ : ranges_)[id][reason];
  if (tally.count++ == 0) tally.first = source + ":" + std::to_string(line);
  ++total_;
}

void LogDrops::Add(const LogDrops& other) {
  for (const auto* by_id : {&other.ranges_, &other.poses_}) {
    for (const auto& [id, reasons] : *by_id) {
      for (const auto& [reason, tally] : reasons) {
        DropTally& into = (IsPoseDrop(reason) ? poses_ : ranges_)[id][reason];
        if (into.count == 0) into.first = tally.first;
        into.count += tally.count;
        total_ += tally.count;
      }
    }
  }
}

std::int64_t LogDrops::Total(Drop reason) const {
  std::int64_t sum = 0;
  for (const auto& [id, reasons] : IsPoseDrop(reason) ? poses_ : ranges_) {
    const auto found = reasons.find(reason);
    if (found != reasons.end()) sum += found->second.count;
  }
  return sum;
}

}  // namespace anchorbench::io
