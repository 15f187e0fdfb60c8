#pragma once

#include <optional>
#include <string_view>

#include "anchorbench/io/csv_reader.hpp"

namespace anchorbench::io {

// A row's time from whichever time column a log's header has (docs/real_data.md): seconds in
// t, time, timestamp, stamp, t_s, time_s, timestamp_s (a number, or an ISO-8601 date such as
// 2024-05-01T12:00:03.250Z); milliseconds in t_ms, time_ms, timestamp_ms; microseconds in t_us,
// time_us, timestamp_us; nanoseconds in t_ns, time_ns, timestamp_ns, stamp_ns (whole numbers,
// read as 64-bit integers so a nanosecond epoch stamp keeps its digits).
class LogTime {
 public:
  explicit LogTime(const CsvReader& csv);  // InputError "FILE:1: missing time column ..." if none
  double Seconds(const CsvReader& csv) const;  // InputError "FILE:LINE: ..." if unreadable

 private:
  enum class Unit { kSeconds, kMilliseconds, kMicroseconds, kNanoseconds };
  int column_ = -1;
  Unit unit_ = Unit::kSeconds;
};

// Seconds since 1970-01-01T00:00:00Z of "YYYY-MM-DD[T| ]hh:mm:ss[.fff][Z|+hh:mm|-hh:mm|+hhmm]";
// without a zone the time is taken as UTC. Nothing if the text is not such a date.
std::optional<double> ParseIsoTime(std::string_view text);

}  // namespace anchorbench::io
