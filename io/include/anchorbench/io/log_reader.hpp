#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <istream>
#include <memory>
#include <optional>
#include <queue>
#include <set>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/io/log_policy.hpp"
#include "anchorbench/io/log_time.hpp"
#include "anchorbench/io/recorded_data.hpp"

namespace anchorbench::io {

// Streaming readers of recorded logs (docs/real_data.md): one row in memory at a time, apart from
// the rows of one time stamp and, with out_of_order: sort, the rows of the sort window. Rows the
// policy drops are counted in a LogDrops; a malformed file is an InputError "FILE:LINE: ...".
//
// Column names (any one of each list; the first row is the header):
//   time    see LogTime (seconds, ms, us, ns or ISO-8601 dates)
//   tag     tag_id, ID_Tag, tag                 (optional: poses without it are tag 0, ranges
//                                                without it belong to the poses' only tag)
//   anchor  anchor_id, ID_Anchor, anchor        (optional in a file of one anchor whose name ends
//                                                in its number: anchor_3.csv, A3.csv)
//   range   range, range_m, distance, distance_m, dist
//   x y z   x, px, p_x, pos_x, position_x (and the same for y and z)

// Rows of one time stamp held at most (a log repeating one stamp without end is refused).
inline constexpr std::size_t kMaxRowsPerTime = 100000;

// Rows in time order under the policy: at once (error or drop a late row), or through a window
// (sort). Records carry t_s and line.
template <typename Record>
class TimeOrder {
 public:
  explicit TimeOrder(const LogPolicy& policy) : policy_(policy) {}
  enum class Verdict { kAccepted, kLate, kTooLate };  // kTooLate: beyond the sort window
  Verdict Push(const Record& record);
  bool Pop(Record& record, bool end_of_input);
  double t_newest_s() const { return t_newest_s_; }
  std::int64_t reordered() const { return reordered_; }  // late rows put in order (kSort)

 private:
  struct Entry {
    Record record;
    std::uint64_t seq;  // file order among equal times
  };
  struct Later {
    bool operator()(const Entry& a, const Entry& b) const {
      return a.record.t_s > b.record.t_s || (a.record.t_s == b.record.t_s && a.seq > b.seq);
    }
  };
  LogPolicy policy_;
  std::priority_queue<Entry, std::vector<Entry>, Later> heap_;
  std::uint64_t seq_ = 0;
  double t_newest_s_ = -std::numeric_limits<double>::infinity();
  std::int64_t reordered_ = 0;
};

class PoseStream {
 public:
  PoseStream(std::istream& in, std::string source, const LogPolicy& policy, LogDrops& drops);
  bool Next(PoseRecord& pose);  // the next pose in time order; false at the end
  std::uint64_t bytes_read() const { return csv_.bytes_read(); }
  std::int64_t rows() const { return rows_; }
  std::int64_t reordered() const { return order_.reordered(); }

 private:
  bool NextOrdered(PoseRecord& pose);
  bool FillGroup();
  void Resolve();  // rows_at_t_ -> group_: repeats dropped, conflicts by the policy, jumps dropped
  bool IsJump(const PoseRecord& pose);  // farther from the tag's last pose than max_speed_mps allows
  void Dropped(Drop reason, const PoseRecord& pose, const std::string& why);

  CsvReader csv_;
  LogPolicy policy_;
  LogDrops& drops_;
  LogTime time_;
  int tag_ = -1, x_ = -1, y_ = -1, z_ = -1;
  TimeOrder<PoseRecord> order_;
  bool at_end_ = false;
  std::int64_t rows_ = 0;
  std::vector<PoseRecord> rows_at_t_, group_;
  std::vector<Eigen::Vector3d> group_sum_;
  std::vector<int> group_count_;
  std::unordered_map<int, std::size_t> group_index_;  // tag -> its pose in group_
  std::size_t group_next_ = 0;
  std::optional<PoseRecord> lookahead_;
  std::unordered_map<int, PoseRecord> last_kept_, last_jump_;  // per tag
};

class RangeStream {
 public:
  // `file_anchor_id` is the anchor of a file without an anchor column (from its name);
  // `default_tag_id` the tag of a file without a tag column.
  RangeStream(std::istream& in, std::string source, int file_index, const LogPolicy& policy, LogDrops& drops,
              std::optional<int> file_anchor_id, std::optional<int> default_tag_id);
  bool Next(RangeRecord& range);  // the next range in time order; false at the end
  std::uint64_t bytes_read() const { return csv_.bytes_read(); }
  std::int64_t rows() const { return rows_; }
  std::int64_t reordered() const { return order_.reordered(); }

 private:
  bool NextOrdered(RangeRecord& range);
  bool IsDuplicate(const RangeRecord& range);
  void Dropped(Drop reason, const RangeRecord& range, const std::string& why);

  CsvReader csv_;
  int file_index_;
  LogPolicy policy_;
  LogDrops& drops_;
  LogTime time_;
  int tag_ = -1, anchor_ = -1, range_ = -1;
  std::optional<int> file_anchor_id_, default_tag_id_;
  TimeOrder<RangeRecord> order_;
  bool at_end_ = false;
  std::int64_t rows_ = 0;
  // The kept rows of the newest time, for exact duplicates: (tag, anchor, range's bits).
  struct RowKey {
    int tag_id, anchor_id;
    std::uint64_t range_bits;
    bool operator==(const RowKey&) const = default;
  };
  struct RowKeyHash {
    std::size_t operator()(const RowKey& k) const;
  };
  double t_rows_s_ = 0.0;
  std::unordered_set<RowKey, RowKeyHash> rows_at_t_;
};

// The number a ranges file's name ends in ("anchor_3.csv", "A12.csv"), if any.
std::optional<int> AnchorIdFromFileName(const std::filesystem::path& path);

// A recording on disk: one poses file, one or more ranges files (e.g. one per anchor).
struct LogFiles {
  std::string poses;
  std::vector<std::string> ranges;
};

using ByteProgress = std::function<void(std::uint64_t bytes_done, std::uint64_t bytes_total)>;

// What a first pass over a log found: its tags and anchors, its row counts and drops.
struct LogSurvey {
  std::set<int> tag_ids;     // of the poses kept
  std::set<int> anchor_ids;  // of the ranges kept
  std::optional<int> default_tag_id;  // the poses' only tag, for ranges without a tag column
  std::int64_t pose_rows = 0, range_rows = 0;  // data rows read
  std::int64_t reordered_rows = 0;             // rows put back in time order (LogPolicy::kSort)
  double t_first_pose_s = 0.0, t_last_pose_s = 0.0;  // the span of the poses kept
  std::uint64_t bytes = 0;
  LogDrops drops;
};

// Reads every file to the end under the policy, so a malformed file or a row the policy refuses
// is found before any work. Throws InputError.
LogSurvey SurveyLog(const LogFiles& files, const LogPolicy& policy, const ByteProgress& progress = nullptr);

// The rows of a recording merged in time order, one at a time: poses before ranges at equal
// times, ranges of several files by time (file order at equal times).
class RecordedLog {
 public:
  RecordedLog(const LogFiles& files, const LogPolicy& policy, std::optional<int> default_tag_id, LogDrops& drops);
  ~RecordedLog();
  enum class Kind { kPose, kRange };
  bool Next(Kind& kind, PoseRecord& pose, RangeRecord& range);
  std::uint64_t bytes_read() const;
  const std::string& range_source(int file) const { return files_.ranges[static_cast<std::size_t>(file)]; }

 private:
  LogFiles files_;
  std::vector<std::unique_ptr<std::ifstream>> inputs_;
  std::unique_ptr<PoseStream> poses_;
  std::vector<std::unique_ptr<RangeStream>> ranges_;
  std::optional<PoseRecord> pose_head_;
  std::vector<std::optional<RangeRecord>> range_heads_;
};

}  // namespace anchorbench::io
