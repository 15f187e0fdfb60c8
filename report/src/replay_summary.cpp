#include "anchorbench/report/replay_summary.hpp"

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "anchorbench/io/format.hpp"

namespace anchorbench::report {
namespace {

using io::FormatNumber;

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

// {id: {reason: {count, first}}}, ids ascending (as JSON keys: text).
nlohmann::ordered_json JsonDrops(const ById& by_id) {
  nlohmann::ordered_json drops = nlohmann::ordered_json::object();
  for (const auto& [id, reasons] : by_id) {
    nlohmann::ordered_json& of_id = drops[std::to_string(id)] = nlohmann::ordered_json::object();
    for (const auto& [reason, tally] : reasons) of_id[io::NameOf(reason)] = {{"count", tally.count}, {"first", tally.first}};
  }
  return drops;
}

}  // namespace

void WriteReplaySummaryJson(std::ostream& out, const ReplaySummary& s) {
  nlohmann::ordered_json json;
  json["poses"] = s.files.poses;
  json["ranges"] = s.files.ranges;
  json["policy"] = {{"max_range_m", s.policy.max_range_m},
                    {"repeated_poses", io::NameOf(s.policy.repeated_poses)},
                    {"out_of_order", io::NameOf(s.policy.out_of_order)},
                    {"sort_window_s", s.policy.sort_window_s},
                    {"repeated_pose_tolerance_m", s.policy.repeated_pose_tolerance_m},
                    {"average_within_m", s.policy.average_within_m},
                    {"max_speed_mps", s.policy.max_speed_mps},
                    {"strict", s.policy.strict}};
  json["pose_rows"] = s.pose_rows;
  json["range_rows"] = s.range_rows;
  json["reordered_rows"] = s.reordered_rows;
  json["samples"] = Samples(s);
  json["dropped"] = s.drops.total();
  nlohmann::ordered_json& by_anchor = json["samples_by_anchor"] = nlohmann::ordered_json::object();
  for (const auto& [anchor, count] : s.samples_by_anchor) by_anchor[std::to_string(anchor)] = count;
  json["range_drops_by_anchor"] = JsonDrops(s.drops.ranges_by_anchor());
  json["pose_drops_by_tag"] = JsonDrops(s.drops.poses_by_tag());
  // Bytes that are not UTF-8 (a path, a log's line) become U+FFFD rather than an exception.
  out << json.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << '\n';
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
