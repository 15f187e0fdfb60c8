#pragma once

#include <fstream>
#include <initializer_list>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace anchorbench::io {

// A strict reader for the project's CSV files: a header line, then one record per line. Every
// error is an InputError "SOURCE:LINE: ..." naming the column. Numbers must parse completely and
// be finite; empty lines are skipped; a '#' in the first column marks a comment line. It reads
// any stream (a file, a string buffer for a fuzzer), one line at a time.
class CsvReader {
 public:
  // `source` names the stream in messages (the file's path).
  CsvReader(std::istream& in, std::string source);

  // Index of the first of `names` (a column and its aliases) present in the header.
  int Column(std::initializer_list<std::string_view> names) const;
  int OptionalColumn(std::initializer_list<std::string_view> names) const;  // -1 if absent

  bool Next();  // false at end of input
  double Number(int column) const;
  int Integer(int column) const;
  bool Empty(int column) const;
  int line() const { return line_; }
  const std::string& source() const { return source_; }
  [[noreturn]] void Fail(const std::string& message) const;  // "SOURCE:LINE: message"

 private:
  std::string_view Field(int column) const;
  template <typename T>
  T Parse(int column, const char* what) const;

  std::istream& in_;
  std::string source_;
  std::vector<std::string> header_;
  std::string text_;
  std::vector<std::string_view> fields_;
  int line_ = 0;
};

// The file, open for reading, or an InputError "PATH: cannot open the file".
std::ifstream OpenForReading(const std::string& path);

}  // namespace anchorbench::io
