#include "anchorbench/io/format.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace anchorbench::io {

std::string FormatNumber(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (std::isnan(value)) return "nan";  // never written by the project; kept visible if it happens
  char buffer[64];
  const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, ptr);
}

std::string FormatFixed(double value, int decimals) {
  if (!std::isfinite(value)) return "-";
  char buffer[512];  // |value| up to 1e308 in fixed notation
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
  return buffer;
}

std::string FormatFixed(const std::optional<double>& value, int decimals) {
  return value ? FormatFixed(*value, decimals) : "-";
}

std::string FormatInterval(const std::optional<double>& lo, const std::optional<double>& hi, int decimals) {
  return lo && hi ? " [" + FormatFixed(*lo, decimals) + ", " + FormatFixed(*hi, decimals) + "]" : std::string();
}

std::string FormatWithInterval(const std::optional<double>& value, const std::optional<double>& lo,
                               const std::optional<double>& hi, int decimals) {
  return value ? FormatFixed(*value, decimals) + FormatInterval(lo, hi, decimals) : "-";
}

std::string FormatOptional(const std::optional<double>& value) { return value ? FormatNumber(*value) : ""; }


}  // namespace anchorbench::io
