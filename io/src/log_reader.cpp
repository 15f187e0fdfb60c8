#include "anchorbench/io/log_reader.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>

#include "anchorbench/io/format.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::io {
namespace {

std::string PositionText(const Eigen::Vector3d& p) {
  std::string text = "(";  // appended, not "(" + ...: GCC 12 warns falsely (-Wrestrict) on that
  text += FormatNumber(p.x());
  text += ", ";
  text += FormatNumber(p.y());
  text += ", ";
  text += FormatNumber(p.z());
  text += ')';
  return text;
}

std::string LateMessage(double t_s, double t_newest_s) {
  return "time goes backwards (t=" + FormatNumber(t_s) + " after t=" + FormatNumber(t_newest_s) +
         "); --out-of-order drop or sort accepts such rows";
}

std::string TooLateMessage(double t_s, double t_newest_s, double window_s) {
  return "t=" + FormatNumber(t_s) + " comes after t=" + FormatNumber(t_newest_s) + ", more than --sort-window-s " +
         FormatNumber(window_s) + " late (a larger --sort-window-s, or --out-of-order drop, accepts it)";
}

void CheckGroupSize(const CsvReader& csv, std::size_t rows, double t_s) {
  if (rows > kMaxRowsPerTime) {
    csv.Fail("more than " + std::to_string(kMaxRowsPerTime) + " rows share the time t=" + FormatNumber(t_s));
  }
}

enum class Row { kEnd, kDropped, kRead };

// A row the policy drops: counted under `id` (anchor or tag), or with --strict the error it is.
void CountOrFail(const LogPolicy& policy, const CsvReader& csv, LogDrops& drops, Drop reason, int id, int line,
                 const std::string& why) {
  if (policy.strict) csv.FailAt(line, why + " (--strict)");
  drops.Count(reason, id, csv.source(), line);
}

// The next row in time order: rows read by `read` (which parses and judges one, or says the file
// ended) go through the policy's order; a late row is an error, or dropped by `drop_late`.
template <typename Record, typename Read, typename DropLate>
bool NextInOrder(TimeOrder<Record>& order, bool& at_end, const CsvReader& csv, const LogPolicy& policy, Read read,
                 DropLate drop_late, Record& out) {
  while (true) {
    if (order.Pop(out, at_end)) return true;
    if (at_end) return false;
    Record row;
    const Row result = read(row);
    if (result == Row::kEnd) at_end = true;
    if (result != Row::kRead) continue;
    switch (order.Push(row)) {
      case TimeOrder<Record>::Verdict::kAccepted: break;
      case TimeOrder<Record>::Verdict::kLate:
        if (policy.out_of_order == LogPolicy::OutOfOrder::kError) csv.Fail(LateMessage(row.t_s, order.t_newest_s()));
        drop_late(row, LateMessage(row.t_s, order.t_newest_s()));
        break;
      case TimeOrder<Record>::Verdict::kTooLate:
        csv.Fail(TooLateMessage(row.t_s, order.t_newest_s(), policy.sort_window_s));
    }
  }
}

}  // namespace

template <typename Record>
typename TimeOrder<Record>::Verdict TimeOrder<Record>::Push(const Record& record) {
  const bool sorting = policy_.out_of_order == LogPolicy::OutOfOrder::kSort;
  if (record.t_s < t_newest_s_) {
    if (!sorting) return Verdict::kLate;
    if (record.t_s < t_newest_s_ - policy_.sort_window_s) return Verdict::kTooLate;
    ++reordered_;
  }
  t_newest_s_ = std::max(t_newest_s_, record.t_s);
  heap_.push({record, seq_++});
  return Verdict::kAccepted;
}

template <typename Record>
bool TimeOrder<Record>::Pop(Record& record, bool end_of_input) {
  if (heap_.empty()) return false;
  // Sorting, a row leaves once no row still allowed to come can be older (see Push).
  const bool sorting = policy_.out_of_order == LogPolicy::OutOfOrder::kSort;
  if (sorting && !end_of_input && !(heap_.top().record.t_s < t_newest_s_ - policy_.sort_window_s)) return false;
  record = heap_.top().record;
  heap_.pop();
  return true;
}

template class TimeOrder<PoseRecord>;
template class TimeOrder<RangeRecord>;

// ---------------------------------------------------------------------------------------------
// Poses

PoseStream::PoseStream(std::istream& in, std::string source, const LogPolicy& policy, LogDrops& drops)
    : csv_(in, std::move(source)), policy_(policy), drops_(drops), time_(csv_), order_(policy) {
  tag_ = csv_.OptionalColumn({"tag_id", "ID_Tag", "tag"});
  x_ = csv_.Column({"x", "px", "p_x", "pos_x", "position_x"});
  y_ = csv_.Column({"y", "py", "p_y", "pos_y", "position_y"});
  z_ = csv_.Column({"z", "pz", "p_z", "pos_z", "position_z"});
}

void PoseStream::Dropped(Drop reason, const PoseRecord& pose, const std::string& why) {
  CountOrFail(policy_, csv_, drops_, reason, pose.tag_id, pose.line, why);
}

bool PoseStream::NextOrdered(PoseRecord& pose) {
  auto read = [this](PoseRecord& row) {
    if (!csv_.Next()) return Row::kEnd;
    ++rows_;
    row.line = csv_.line();
    row.t_s = time_.Seconds(csv_);
    row.tag_id = tag_ >= 0 ? csv_.Integer(tag_) : 0;
    row.p_world_tag = {csv_.NumberOrNonFinite(x_), csv_.NumberOrNonFinite(y_), csv_.NumberOrNonFinite(z_)};
    if (row.p_world_tag.allFinite()) return Row::kRead;
    Dropped(Drop::kPoseNotFinite, row, "position " + PositionText(row.p_world_tag) + " is not finite");
    return Row::kDropped;
  };
  auto drop_late = [this](const PoseRecord& row, const std::string& why) { Dropped(Drop::kLatePose, row, why); };
  return NextInOrder(order_, at_end_, csv_, policy_, read, drop_late, pose);
}

bool PoseStream::FillGroup() {
  rows_at_t_.clear();
  PoseRecord row;
  if (lookahead_) {
    rows_at_t_.push_back(*lookahead_);
    lookahead_.reset();
  } else if (NextOrdered(row)) {
    rows_at_t_.push_back(row);
  } else {
    return false;
  }
  while (NextOrdered(row)) {
    if (row.t_s != rows_at_t_.front().t_s) {
      lookahead_ = row;
      break;
    }
    rows_at_t_.push_back(row);
    CheckGroupSize(csv_, rows_at_t_.size(), row.t_s);
  }
  Resolve();
  return true;
}

void PoseStream::Resolve() {
  group_.clear();
  group_sum_.clear();
  group_count_.clear();
  group_index_.clear();
  group_next_ = 0;
  for (const PoseRecord& row : rows_at_t_) {
    const auto [found, is_new] = group_index_.emplace(row.tag_id, group_.size());  // the tag's first row of this time
    const std::size_t kept = found->second;
    if (is_new) {
      group_.push_back(row);
      group_sum_.push_back(row.p_world_tag);
      group_count_.push_back(1);
      continue;
    }
    const PoseRecord& first = group_[kept];
    if ((row.p_world_tag - first.p_world_tag).norm() <= policy_.repeated_pose_tolerance_m) {
      Dropped(Drop::kRepeatedPose, row,
              "tag " + std::to_string(row.tag_id) + " repeats its pose of line " + std::to_string(first.line));
      continue;
    }
    const double apart_m = (row.p_world_tag - first.p_world_tag).norm();
    const std::string conflict = "tag " + std::to_string(row.tag_id) + " has another pose at t=" +
                                 FormatNumber(row.t_s) + ": " + PositionText(row.p_world_tag) + " here, " +
                                 PositionText(first.p_world_tag) + " at line " + std::to_string(first.line);
    const LogPolicy::RepeatedPoses policy =
        apart_m <= policy_.average_within_m ? LogPolicy::RepeatedPoses::kAverage : policy_.repeated_poses;
    switch (policy) {
      case LogPolicy::RepeatedPoses::kError:
        csv_.FailAt(row.line, conflict + " (" + FormatNumber(apart_m) + " m apart, beyond --average-poses-within-m " +
                                  FormatNumber(policy_.average_within_m) + "); --repeated-poses first or average accepts it");
      case LogPolicy::RepeatedPoses::kFirst: Dropped(Drop::kConflictingPose, row, conflict); break;
      case LogPolicy::RepeatedPoses::kAverage:
        Dropped(Drop::kAveragedPose, row, conflict);
        group_sum_[kept] += row.p_world_tag;
        ++group_count_[kept];
        break;
    }
  }
  for (std::size_t i = 0; i < group_.size(); ++i) {
    if (group_count_[i] > 1) group_[i].p_world_tag = group_sum_[i] / group_count_[i];
  }
  std::erase_if(group_, [this](const PoseRecord& pose) { return IsJump(pose); });
}

// A pose is judged against its tag's last kept pose: beyond max_speed_mps it is dropped, unless
// the pose dropped just before agrees with it (a lasting jump: the tag is there now).
bool PoseStream::IsJump(const PoseRecord& pose) {
  const auto consistent = [this](const PoseRecord& from, const PoseRecord& to) {
    const double distance_m = (to.p_world_tag - from.p_world_tag).norm();
    return distance_m <= policy_.max_speed_mps * std::abs(to.t_s - from.t_s) + 1e-9;
  };
  const auto kept = last_kept_.find(pose.tag_id);
  const auto jump = last_jump_.find(pose.tag_id);
  if (kept == last_kept_.end() || consistent(kept->second, pose) ||
      (jump != last_jump_.end() && consistent(jump->second, pose))) {
    last_kept_.insert_or_assign(pose.tag_id, pose);
    if (jump != last_jump_.end()) last_jump_.erase(jump);
    return false;
  }
  Dropped(Drop::kPoseJump, pose,
          "tag " + std::to_string(pose.tag_id) + " jumps to " + PositionText(pose.p_world_tag) + " from " +
              PositionText(kept->second.p_world_tag) + " at line " + std::to_string(kept->second.line) +
              ", faster than --max-speed-mps " + FormatNumber(policy_.max_speed_mps));
  last_jump_.insert_or_assign(pose.tag_id, pose);
  return true;
}

bool PoseStream::Next(PoseRecord& pose) {
  while (group_next_ == group_.size()) {
    if (!FillGroup()) return false;
  }
  pose = group_[group_next_++];
  return true;
}

// ---------------------------------------------------------------------------------------------
// Ranges

RangeStream::RangeStream(std::istream& in, std::string source, int file_index, const LogPolicy& policy,
                         LogDrops& drops, std::optional<int> file_anchor_id, std::optional<int> default_tag_id)
    : csv_(in, std::move(source)), file_index_(file_index), policy_(policy), drops_(drops), time_(csv_),
      file_anchor_id_(file_anchor_id), default_tag_id_(default_tag_id), order_(policy) {
  tag_ = default_tag_id_ ? csv_.OptionalColumn({"tag_id", "ID_Tag", "tag"}) : csv_.Column({"tag_id", "ID_Tag", "tag"});
  anchor_ = csv_.OptionalColumn({"anchor_id", "ID_Anchor", "anchor"});
  if (anchor_ < 0 && !file_anchor_id_) {
    throw schema::InputError(csv_.source() + ":1: missing column 'anchor_id' (or 'ID_Anchor', 'anchor'), and the file's "
                                     "name does not end in an anchor number");
  }
  range_ = csv_.Column({"range", "range_m", "distance", "distance_m", "dist"});
}

void RangeStream::Dropped(Drop reason, const RangeRecord& range, const std::string& why) {
  CountOrFail(policy_, csv_, drops_, reason, range.anchor_id, range.line, why);
}

bool RangeStream::NextOrdered(RangeRecord& range) {
  auto read = [this](RangeRecord& row) {
    if (!csv_.Next()) return Row::kEnd;
    ++rows_;
    row.line = csv_.line();
    row.file = file_index_;
    row.t_s = time_.Seconds(csv_);
    row.tag_id = tag_ >= 0 ? csv_.Integer(tag_) : *default_tag_id_;
    row.anchor_id = anchor_ >= 0 ? csv_.Integer(anchor_) : *file_anchor_id_;
    row.range_m = csv_.NumberOrNonFinite(range_);
    const std::string value = "range " + FormatNumber(row.range_m);
    if (!std::isfinite(row.range_m)) {
      Dropped(Drop::kRangeNotFinite, row, value + " is not finite");
    } else if (row.range_m <= 0.0) {
      Dropped(Drop::kRangeNotPositive, row, value + " is not positive");
    } else if (row.range_m > policy_.max_range_m) {
      Dropped(Drop::kRangeBeyondMax, row, value + " is beyond --max-range-m " + FormatNumber(policy_.max_range_m));
    } else {
      return Row::kRead;
    }
    return Row::kDropped;
  };
  auto drop_late = [this](const RangeRecord& row, const std::string& why) { Dropped(Drop::kLateRange, row, why); };
  return NextInOrder(order_, at_end_, csv_, policy_, read, drop_late, range);
}

std::size_t RangeStream::RowKeyHash::operator()(const RowKey& k) const {
  std::uint64_t h = k.range_bits * 0x9E3779B97F4A7C15ull;
  h ^= (static_cast<std::uint64_t>(static_cast<std::uint32_t>(k.tag_id)) << 32 | static_cast<std::uint32_t>(k.anchor_id)) +
       0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
  return static_cast<std::size_t>(h);
}

bool RangeStream::IsDuplicate(const RangeRecord& range) {
  if (!rows_at_t_.empty() && t_rows_s_ != range.t_s) rows_at_t_.clear();
  t_rows_s_ = range.t_s;
  std::uint64_t bits = 0;
  std::memcpy(&bits, &range.range_m, sizeof(bits));
  if (!rows_at_t_.insert({range.tag_id, range.anchor_id, bits}).second) return true;
  CheckGroupSize(csv_, rows_at_t_.size(), range.t_s);
  return false;
}

bool RangeStream::Next(RangeRecord& range) {
  while (NextOrdered(range)) {
    if (!IsDuplicate(range)) return true;
    Dropped(Drop::kDuplicateRange, range, "a repeat of an earlier row");
  }
  return false;
}

// ---------------------------------------------------------------------------------------------
// Files

std::optional<int> AnchorIdFromFileName(const std::filesystem::path& path) {
  // Only a name that ends in its number ("anchor_3", "A12"), not one with a number inside ("3_log").
  const std::string stem = path.stem().string();
  std::size_t start = stem.size();
  while (start > 0 && std::isdigit(static_cast<unsigned char>(stem[start - 1]))) --start;
  int id = 0;
  if (start == stem.size()) return std::nullopt;
  if (std::from_chars(stem.data() + start, stem.data() + stem.size(), id).ec != std::errc()) return std::nullopt;
  return id;
}

namespace {

std::uint64_t FileBytes(const std::string& path) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  return error ? 0 : static_cast<std::uint64_t>(size);
}

}  // namespace

namespace {

// A log is read twice (checked, then streamed): a pipe would read empty the second time. And a
// file named twice would count every row twice.
void CheckLogFiles(const LogFiles& files) {
  std::vector<std::string> paths = {files.poses};
  paths.insert(paths.end(), files.ranges.begin(), files.ranges.end());
  std::error_code error;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const std::filesystem::file_status status = std::filesystem::status(paths[i], error);
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
        !std::filesystem::is_directory(status)) {
      throw schema::InputError(paths[i] + ": is not a regular file (a pipe or a device): the log is read twice, once to "
                               "check it; save it to a file first");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (std::filesystem::equivalent(paths[i], paths[j], error)) {
        throw schema::InputError(paths[i] + ": is given twice (also as " + paths[j] + "); each row would count twice");
      }
    }
  }
}

}  // namespace

LogSurvey SurveyLog(const LogFiles& files, const LogPolicy& policy, const ByteProgress& progress) {
  CheckLogFiles(files);
  LogSurvey survey;
  std::uint64_t total = FileBytes(files.poses), before = 0;
  for (const std::string& path : files.ranges) total += FileBytes(path);
  std::int64_t rows = 0;
  auto report = [&](std::uint64_t bytes) {
    if (progress && (++rows & 0xffff) == 0) progress(before + bytes, total);
  };
  {
    std::ifstream in = OpenForReading(files.poses);
    PoseStream poses(in, files.poses, policy, survey.drops);
    PoseRecord pose;
    bool first = true;
    while (poses.Next(pose)) {
      survey.tag_ids.insert(pose.tag_id);
      survey.t_first_pose_s = first ? pose.t_s : std::min(survey.t_first_pose_s, pose.t_s);
      survey.t_last_pose_s = first ? pose.t_s : std::max(survey.t_last_pose_s, pose.t_s);
      first = false;
      report(poses.bytes_read());
    }
    survey.pose_rows = poses.rows();
    survey.reordered_rows += poses.reordered();
    before += poses.bytes_read();
  }
  if (survey.tag_ids.empty()) throw schema::InputError(files.poses + ": no poses");
  if (survey.tag_ids.size() == 1) survey.default_tag_id = *survey.tag_ids.begin();
  for (std::size_t f = 0; f < files.ranges.size(); ++f) {
    std::ifstream in = OpenForReading(files.ranges[f]);
    RangeStream ranges(in, files.ranges[f], static_cast<int>(f), policy, survey.drops,
                       AnchorIdFromFileName(files.ranges[f]), survey.default_tag_id);
    RangeRecord range;
    while (ranges.Next(range)) {
      if (survey.anchor_ids.insert(range.anchor_id).second && survey.anchor_ids.size() > policy.max_anchors) {
        throw schema::InputError(files.ranges[f] + ":" + std::to_string(range.line) + ": anchor " +
                         std::to_string(range.anchor_id) + " is a distinct anchor beyond the " +
                         std::to_string(policy.max_anchors) + " anchors a log may hold (the front end's max_anchors)");
      }
      report(ranges.bytes_read());
    }
    survey.range_rows += ranges.rows();
    survey.reordered_rows += ranges.reordered();
    before += ranges.bytes_read();
  }
  survey.bytes = before;
  if (progress) progress(total, total);
  return survey;
}

RecordedLog::RecordedLog(const LogFiles& files, const LogPolicy& policy, std::optional<int> default_tag_id,
                         LogDrops& drops)
    : files_(files) {
  inputs_.push_back(std::make_unique<std::ifstream>(OpenForReading(files_.poses)));
  poses_ = std::make_unique<PoseStream>(*inputs_.back(), files_.poses, policy, drops);
  for (std::size_t f = 0; f < files_.ranges.size(); ++f) {
    inputs_.push_back(std::make_unique<std::ifstream>(OpenForReading(files_.ranges[f])));
    ranges_.push_back(std::make_unique<RangeStream>(*inputs_.back(), files_.ranges[f], static_cast<int>(f), policy,
                                                    drops, AnchorIdFromFileName(files_.ranges[f]), default_tag_id));
  }
  PoseRecord pose;
  if (poses_->Next(pose)) pose_head_ = pose;
  range_heads_.resize(ranges_.size());
  for (std::size_t f = 0; f < ranges_.size(); ++f) {
    RangeRecord range;
    if (ranges_[f]->Next(range)) range_heads_[f] = range;
  }
}

RecordedLog::~RecordedLog() = default;

bool RecordedLog::Next(Kind& kind, PoseRecord& pose, RangeRecord& range) {
  std::size_t earliest = range_heads_.size();
  for (std::size_t f = 0; f < range_heads_.size(); ++f) {
    if (range_heads_[f] && (earliest == range_heads_.size() || range_heads_[f]->t_s < range_heads_[earliest]->t_s)) {
      earliest = f;
    }
  }
  const bool have_range = earliest < range_heads_.size();
  if (pose_head_ && (!have_range || pose_head_->t_s <= range_heads_[earliest]->t_s)) {
    kind = Kind::kPose;
    pose = *pose_head_;
    pose_head_.reset();
    PoseRecord next;
    if (poses_->Next(next)) pose_head_ = next;
    return true;
  }
  if (!have_range) return false;
  kind = Kind::kRange;
  range = *range_heads_[earliest];
  range_heads_[earliest].reset();
  RangeRecord next;
  if (ranges_[earliest]->Next(next)) range_heads_[earliest] = next;
  return true;
}

std::uint64_t RecordedLog::bytes_read() const {
  std::uint64_t bytes = poses_->bytes_read();
  for (const auto& ranges : ranges_) bytes += ranges->bytes_read();
  return bytes;
}

}  // namespace anchorbench::io
