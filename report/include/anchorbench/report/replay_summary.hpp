#pragma once

#include <cstdint>
#include <map>
#include <ostream>

#include "anchorbench/io/log_reader.hpp"

namespace anchorbench::report {

// What a replay read, used and dropped (docs/real_data.md).
struct ReplaySummary {
  io::LogFiles files;
  io::LogPolicy policy;
  std::int64_t pose_rows = 0, range_rows = 0;  // data rows in the files
  std::map<int, std::int64_t> samples_by_anchor;  // ranges handed to the initializers
  io::LogDrops drops;  // the readers' and the front end's
  std::int64_t reordered_rows = 0;  // rows put back in time order (kept, counted)
};

// replay_summary.json: inputs, policy, row counts, and per anchor / tag each drop reason with its
// count and first FILE:LINE. No times: the same log gives the same bytes.
void WriteReplaySummaryJson(std::ostream& out, const ReplaySummary& summary);
// replay_summary.md: one line of totals, then a table of anchors with drops.
void WriteReplaySummaryMarkdown(std::ostream& out, const ReplaySummary& summary);
// A few lines for stderr: totals, and each reason with its count and first row.
void PrintReplaySummary(std::ostream& err, const ReplaySummary& summary);

}  // namespace anchorbench::report
