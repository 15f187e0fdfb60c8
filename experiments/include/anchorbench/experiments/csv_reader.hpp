#pragma once

#include <fstream>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace anchorbench::experiments {

// A strict reader for the project's CSV files: a header line, then one record per line. Every
// error is an InputError "FILE:LINE: ..." naming the column. Numbers must parse completely and
// be finite; empty lines are skipped; a '#' in the first column marks a comment line.
class CsvReader {
 public:
  explicit CsvReader(std::string path);

  // Index of the first of `names` (a column and its aliases) present in the header.
  int Column(std::initializer_list<std::string_view> names) const;
  int OptionalColumn(std::initializer_list<std::string_view> names) const;  // -1 if absent

  bool Next();  // false at end of file
  double Number(int column) const;
  int Integer(int column) const;
  bool Empty(int column) const;
  int line() const { return line_; }
  const std::string& path() const { return path_; }
  [[noreturn]] void Fail(const std::string& message) const;  // at the current line

 private:
  std::string_view Field(int column) const;
  template <typename T>
  T Parse(int column, const char* what) const;

  std::string path_;
  std::ifstream in_;
  std::vector<std::string> header_;
  std::string text_;
  std::vector<std::string_view> fields_;
  int line_ = 0;
};

// Shortest decimal text that reads back to the same double ("inf" for infinity): deterministic,
// locale-free, and lossless, so equal results give equal bytes.
std::string FormatNumber(double value);

// Fixed decimals for tables meant to be read ("0.125"); "-" for a non-finite value.
std::string FormatFixed(double value, int decimals);

}  // namespace anchorbench::experiments
