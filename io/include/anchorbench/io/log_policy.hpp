#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace anchorbench::io {

// What a recorded log may contain besides clean rows, and what is done with it (docs/real_data.md).
// A malformed file (an unparseable number, a missing column, a wrong field count) is always an
// error; these are the measurements a real radio and a real recorder produce now and then.
struct LogPolicy {
  // Ranges above this are dropped as implausible (a UWB link reaches a few hundred metres).
  double max_range_m = 1000.0;
  // Two pose rows of one tag at one time: within this distance they are one pose repeated (the
  // first kept, the others counted as repeated_pose); within average_within_m they are one pose
  // measured twice (a tracker and a recorder each stamping it: averaged, counted as averaged_pose);
  // farther apart, the policy below decides. 5 cm (ours): above the millimetres of motion capture
  // and the centimetres of a VIO's jitter at one time stamp, below what a tag moves between two
  // 10 Hz poses at walking speed.
  double repeated_pose_tolerance_m = 0.001;
  double average_within_m = 0.05;
  enum class RepeatedPoses { kError, kFirst, kAverage };
  RepeatedPoses repeated_poses = RepeatedPoses::kError;
  // A row older than one read before it (within one file). By default (ours, for real logs)
  // rows up to sort_window_s late are put in order and counted; a later one is an error naming
  // the flag.
  enum class OutOfOrder { kError, kDrop, kSort };
  OutOfOrder out_of_order = OutOfOrder::kSort;
  // With kSort: how late a row may come, in seconds of the file's own time; later is an error.
  double sort_window_s = 0.1;
  // A pose farther from its tag's last pose than this speed allows is dropped (a glitch of the
  // tracker: one pose at x = 1e6 would otherwise bend every range around it), unless the next
  // pose agrees with it (then the tag did jump: a reset of the tracker's frame, kept).
  double max_speed_mps = 50.0;
  // Distinct anchors a log may hold (the front end's estimator::FrontEndOptions::max_anchors):
  // beyond it the log is refused at the first range of the anchor too many, before any work.
  std::size_t max_anchors = 1000;
  // Every drop is an error (file:line, exit 2), as before these rules existed.
  bool strict = false;
};

// Parse the command line's names ("error", "first", "average"; "error", "drop", "sort"); an
// unknown name is std::invalid_argument.
LogPolicy::RepeatedPoses RepeatedPosesFromName(std::string_view name);
LogPolicy::OutOfOrder OutOfOrderFromName(std::string_view name);
const char* NameOf(LogPolicy::RepeatedPoses policy);
const char* NameOf(LogPolicy::OutOfOrder policy);

// Why a row never reached the estimator.
enum class Drop {
  kRangeNotPositive,   // range <= 0
  kRangeNotFinite,     // nan or inf
  kRangeBeyondMax,     // above LogPolicy::max_range_m
  kDuplicateRange,     // the same t, tag, anchor and range as a row before it
  kLateRange,          // older than a row before it (out_of_order: drop)
  kOutsidePoses,       // before the tag's first pose or after its last (never extrapolated)
  kNoPoseInTime,       // its tag's next pose never came within the front end's wait
  kTooManyAnchors,     // of an anchor beyond the front end's max_anchors
  kPoseNotFinite,      // a position coordinate is nan or inf
  kRepeatedPose,       // the same t, tag and position as a row before it
  kConflictingPose,    // the same t and tag, another position: not the first (repeated_poses: first)
  kAveragedPose,       // merged into the average of its time (repeated_poses: average)
  kLatePose,           // older than a row before it (out_of_order: drop)
  kPoseJump,           // farther from the tag's last pose than max_speed_mps allows
};
const char* NameOf(Drop reason);  // snake_case, as in replay_summary.json
bool IsPoseDrop(Drop reason);

// Rows dropped, by anchor (ranges) or tag (poses) and reason, with the first such row's place.
struct DropTally {
  std::int64_t count = 0;
  std::string first;  // "FILE:LINE" of the first row so dropped
};
class LogDrops {
 public:
  void Count(Drop reason, int id, const std::string& source, int line);
  void Add(const LogDrops& other);  // counts summed; the earlier tally's first row kept
  const std::map<int, std::map<Drop, DropTally>>& ranges_by_anchor() const { return ranges_; }
  const std::map<int, std::map<Drop, DropTally>>& poses_by_tag() const { return poses_; }
  std::int64_t total() const { return total_; }
  std::int64_t Total(Drop reason) const;

 private:
  std::map<int, std::map<Drop, DropTally>> ranges_;
  std::map<int, std::map<Drop, DropTally>> poses_;
  std::int64_t total_ = 0;
};

}  // namespace anchorbench::io
