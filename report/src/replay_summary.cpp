#include "anchorbench/report/replay_summary.hpp"

#include <string>
#include <vector>

#include "anchorbench/io/format.hpp"

namespace anchorbench::report {
namespace {

using io::FormatNumber;
using io::JsonString;

using ById = std::map<int, std::map<io::Drop, io::DropTally>>;

std::int64_t Samples(const ReplaySummary& s) {
  std::int64_t n = 0;
  for (const auto& [anchor, count] : s.samples_by_anchor) n += count;
  return n;
}

// Every reason over all ids: count and the first row (the earliest id's, as ids ascend).
std::map<io::Drop, io::DropTally> ByReason(const ById& by_id) {
  std::map<io::Drop, io::DropTally> out;
  for (const auto& [id, reasons] : by_id) {
    for (const auto& [reason, tally] : reasons) {
      io::DropTally& into = out[reason];
      if (into.count == 0) into.first = tally.first;
      into.count += tally.count;
    }
  }
  return out;
}

void JsonDrops(std::ostream& out, const ById& by_id, const char* indent) {
  out << "{";
  bool first_id = true;
  for (const auto& [id, reasons] : by_id) {
    out << (first_id ? "\n" : ",\n") << indent << "  \"" << id << "\": {";
    first_id = false;
    bool first_reason = true;
    for (const auto& [reason, tally] : reasons) {
      out << (first_reason ? "" : ", ") << '"' << io::NameOf(reason) << "\": {\"count\": " << tally.count
          << ", \"first\": " << JsonString(tally.first) << '}';
      first_reason = false;
    }
    out << '}';
  }
  if (!first_id) out << '\n' << indent;
  out << '}';
}

}  // namespace

void WriteReplaySummaryJson(std::ostream& out, const ReplaySummary& s) {
  out << "{\n  \"poses\": " << JsonString(s.files.poses) << ",\n  \"ranges\": [";
  for (std::size_t f = 0; f < s.files.ranges.size(); ++f) out << (f ? ", " : "") << JsonString(s.files.ranges[f]);
  out << "],\n  \"policy\": {\"max_range_m\": " << FormatNumber(s.policy.max_range_m) << ", \"repeated_poses\": \""
      << io::NameOf(s.policy.repeated_poses) << "\", \"out_of_order\": \"" << io::NameOf(s.policy.out_of_order)
      << "\", \"sort_window_s\": " << FormatNumber(s.policy.sort_window_s) << ", \"repeated_pose_tolerance_m\": "
      << FormatNumber(s.policy.repeated_pose_tolerance_m) << ", \"max_speed_mps\": " << FormatNumber(s.policy.max_speed_mps)
      << ", \"strict\": " << (s.policy.strict ? "true" : "false") << "},\n  \"pose_rows\": " << s.pose_rows
      << ",\n  \"range_rows\": " << s.range_rows << ",\n  \"reordered_rows\": " << s.reordered_rows
      << ",\n  \"samples\": " << Samples(s)
      << ",\n  \"dropped\": " << s.drops.total() << ",\n  \"samples_by_anchor\": {";
  bool first = true;
  for (const auto& [anchor, count] : s.samples_by_anchor) {
    out << (first ? "" : ", ") << '"' << anchor << "\": " << count;
    first = false;
  }
  out << "},\n  \"range_drops_by_anchor\": ";
  JsonDrops(out, s.drops.ranges_by_anchor(), "  ");
  out << ",\n  \"pose_drops_by_tag\": ";
  JsonDrops(out, s.drops.poses_by_tag(), "  ");
  out << "\n}\n";
}

void WriteReplaySummaryMarkdown(std::ostream& out, const ReplaySummary& s) {
  out << "# Replay\n\n" << s.pose_rows << " pose rows and " << s.range_rows << " range rows read; " << Samples(s)
      << " ranges handed to the initializers; " << s.drops.total() << " rows dropped; " << s.reordered_rows
      << " rows put back in time order.\n";
  const std::map<io::Drop, io::DropTally> ranges = ByReason(s.drops.ranges_by_anchor());
  const std::map<io::Drop, io::DropTally> poses = ByReason(s.drops.poses_by_tag());
  if (ranges.empty() && poses.empty()) return;
  out << "\n| rows | reason | dropped | first |\n|---|---|---:|---|\n";
  for (const auto& [reason, tally] : ranges) out << "| ranges | " << io::NameOf(reason) << " | " << tally.count << " | " << tally.first << " |\n";
  for (const auto& [reason, tally] : poses) out << "| poses | " << io::NameOf(reason) << " | " << tally.count << " | " << tally.first << " |\n";
  out << "\n| anchor | samples | dropped |\n|---:|---:|---|\n";
  std::map<int, std::string> dropped;
  for (const auto& [anchor, reasons] : s.drops.ranges_by_anchor()) {
    for (const auto& [reason, tally] : reasons) {
      dropped[anchor] += (dropped[anchor].empty() ? "" : ", ") + std::string(io::NameOf(reason)) + " " + std::to_string(tally.count);
    }
  }
  for (const auto& [anchor, count] : s.samples_by_anchor) dropped.emplace(anchor, "");
  for (const auto& [anchor, text] : dropped) {
    const auto samples = s.samples_by_anchor.find(anchor);
    out << "| " << anchor << " | " << (samples == s.samples_by_anchor.end() ? 0 : samples->second) << " | "
        << (text.empty() ? "-" : text) << " |\n";
  }
}

void PrintReplaySummary(std::ostream& err, const ReplaySummary& s) {
  err << "replay: " << s.range_rows << " range rows, " << Samples(s) << " used, " << s.drops.total()
      << " rows dropped" << (s.reordered_rows > 0 ? ", " + std::to_string(s.reordered_rows) + " put back in time order" : "")
      << "\n";
  for (const auto& [kind, by_id] : {std::pair{"ranges", &s.drops.ranges_by_anchor()}, std::pair{"poses", &s.drops.poses_by_tag()}}) {
    for (const auto& [reason, tally] : ByReason(*by_id)) {
      err << "  " << kind << ' ' << io::NameOf(reason) << ": " << tally.count << " (e.g. " << tally.first << ")\n";
    }
  }
}

}  // namespace anchorbench::report
