#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "anchorbench/schema/names.hpp"

namespace anchorbench::io {

// Shortest text that reads back to the same double ("inf"/"-inf" for infinities): CSV cells.
std::string FormatNumber(double value);
// Fixed decimals for tables meant for people; "-" for a non-finite value.
std::string FormatFixed(double value, int decimals);
// FormatFixed, or "-" where there is no value.
std::string FormatFixed(const std::optional<double>& value, int decimals);
// " [lo, hi]" in fixed decimals after a table's value, or "" where there is no interval.
std::string FormatInterval(const std::optional<double>& lo, const std::optional<double>& hi, int decimals);
// A table's value with its interval after it ("0.25 [0.10, 0.40]"), or "-" where there is no value.
std::string FormatWithInterval(const std::optional<double>& value, const std::optional<double>& lo,
                               const std::optional<double>& hi, int decimals);
// FormatNumber, or an empty cell where there is no value (never "nan").
std::string FormatOptional(const std::optional<double>& value);
// The text with control bytes and non-ASCII bytes as \xNN, so a message quoting input stays one
// printable line.
using schema::Printable;

}  // namespace anchorbench::io
