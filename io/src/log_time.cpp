#include "anchorbench/io/log_time.hpp"

#include <cmath>
#include <initializer_list>

#include "anchorbench/io/format.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::io {
namespace {

// Days from 1970-01-01 to the proleptic Gregorian date (H. Hinnant's days_from_civil).
long long DaysFromCivil(long long y, unsigned m, unsigned d) {
  y -= m <= 2 ? 1 : 0;
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const unsigned yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<long long>(doe) - 719468;
}

// Reads `width` digits at `pos`, advancing it.
bool Digits(std::string_view text, std::size_t& pos, int width, int& value) {
  if (pos + static_cast<std::size_t>(width) > text.size()) return false;
  value = 0;
  for (int i = 0; i < width; ++i) {
    const char c = text[pos++];
    if (c < '0' || c > '9') return false;
    value = value * 10 + (c - '0');
  }
  return true;
}

bool Expect(std::string_view text, std::size_t& pos, char c) {
  if (pos >= text.size() || text[pos] != c) return false;
  ++pos;
  return true;
}

}  // namespace

std::optional<double> ParseIsoTime(std::string_view text) {
  std::size_t pos = 0;
  int year = 0, month = 0, day = 0, hour = 0, minute = 0, second = 0;
  if (!Digits(text, pos, 4, year) || !Expect(text, pos, '-') || !Digits(text, pos, 2, month) ||
      !Expect(text, pos, '-') || !Digits(text, pos, 2, day)) {
    return std::nullopt;
  }
  if (pos >= text.size() || (text[pos] != 'T' && text[pos] != ' ')) return std::nullopt;
  ++pos;
  if (!Digits(text, pos, 2, hour) || !Expect(text, pos, ':') || !Digits(text, pos, 2, minute) ||
      !Expect(text, pos, ':') || !Digits(text, pos, 2, second)) {
    return std::nullopt;
  }
  if (month < 1 || month > 12 || day < 1 || day > 31 || hour > 23 || minute > 59 || second > 60) return std::nullopt;
  double fraction = 0.0;
  if (pos < text.size() && (text[pos] == '.' || text[pos] == ',')) {
    ++pos;
    double scale = 0.1;
    const std::size_t first = pos;
    for (; pos < text.size() && text[pos] >= '0' && text[pos] <= '9'; ++pos, scale *= 0.1) fraction += (text[pos] - '0') * scale;
    if (pos == first) return std::nullopt;
  }
  long long offset_s = 0;
  if (pos < text.size() && text[pos] == 'Z') {
    ++pos;
  } else if (pos < text.size() && (text[pos] == '+' || text[pos] == '-')) {
    const int sign = text[pos++] == '-' ? -1 : 1;
    int zone_hours = 0, zone_minutes = 0;
    if (!Digits(text, pos, 2, zone_hours)) return std::nullopt;
    Expect(text, pos, ':');
    if (!Digits(text, pos, 2, zone_minutes) || zone_hours > 23 || zone_minutes > 59) return std::nullopt;
    offset_s = sign * (zone_hours * 3600LL + zone_minutes * 60LL);
  }
  if (pos != text.size()) return std::nullopt;
  const long long whole_s = DaysFromCivil(year, static_cast<unsigned>(month), static_cast<unsigned>(day)) * 86400LL +
                            hour * 3600LL + minute * 60LL + second - offset_s;
  return static_cast<double>(whole_s) + fraction;
}

LogTime::LogTime(const CsvReader& csv) {
  const struct {
    std::initializer_list<std::string_view> names;
    Unit unit;
  } kinds[] = {
      {{"t", "time", "timestamp", "stamp", "t_s", "time_s", "timestamp_s"}, Unit::kSeconds},
      {{"t_ms", "time_ms", "timestamp_ms"}, Unit::kMilliseconds},
      {{"t_us", "time_us", "timestamp_us"}, Unit::kMicroseconds},
      {{"t_ns", "time_ns", "timestamp_ns", "stamp_ns"}, Unit::kNanoseconds},
  };
  for (const auto& kind : kinds) {
    column_ = csv.OptionalColumn(kind.names);
    if (column_ >= 0) {
      unit_ = kind.unit;
      return;
    }
  }
  throw schema::InputError(csv.source() + ":1: missing a time column: t (or time, timestamp, stamp) in seconds or as ISO-8601 "
                                  "dates, or t_ms, t_us, t_ns (docs/real_data.md)");
}

double LogTime::Seconds(const CsvReader& csv) const {
  switch (unit_) {
    case Unit::kSeconds: {
      if (const std::optional<double> iso = ParseIsoTime(csv.Text(column_))) return *iso;
      return csv.Number(column_);
    }
    case Unit::kMilliseconds: return csv.Number(column_) * 1e-3;
    case Unit::kMicroseconds: return csv.Number(column_) * 1e-6;
    case Unit::kNanoseconds: return static_cast<double>(csv.Integer64(column_)) * 1e-9;
  }
  return 0.0;
}

}  // namespace anchorbench::io
