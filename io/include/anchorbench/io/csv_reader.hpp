#pragma once

#include <cstdint>
#include <fstream>
#include <initializer_list>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace anchorbench::io {

// A strict reader for the project's CSV files: a header line, then one record per line. Every
// error is an InputError "SOURCE:LINE: ..." naming the column. Numbers must parse completely and
// be finite; empty lines are skipped; a '#' in the first column marks a comment line; header names
// may be quoted. Lines end in LF, CRLF or a lone CR (old spreadsheets). It reads any stream (a file, a string buffer for a fuzzer), one line at a time,
// reusing its buffers (no allocation per line once warm).
class CsvReader {
 public:
  // `source` names the stream in messages (the file's path); `header_line` is the header's line in
  // it (a text cut from a larger file counts its lines from there).
  CsvReader(std::istream& in, std::string source, int header_line = 1);

  // Index of the first of `names` (a column and its aliases) present in the header.
  int Column(std::initializer_list<std::string_view> names) const;
  int OptionalColumn(std::initializer_list<std::string_view> names) const;  // -1 if absent

  bool Next();  // false at end of input
  double Number(int column) const;
  // A number that may be "nan" or "inf": a measurement the caller judges, not a malformed file.
  double NumberOrNonFinite(int column) const;
  int Integer(int column) const;
  long long Integer64(int column) const;
  bool Empty(int column) const;
  std::string_view Text(int column) const { return Field(column); }
  std::string_view record_text() const { return text_; }  // the current record's line as read
  int columns() const { return static_cast<int>(header_.size()); }
  const std::string& header(int column) const { return header_[static_cast<std::size_t>(column)]; }
  int line() const { return line_; }
  std::uint64_t bytes_read() const { return bytes_read_; }
  const std::string& source() const { return source_; }
  [[noreturn]] void Fail(const std::string& message) const;  // "SOURCE:LINE: message"
  [[noreturn]] void FailAt(int line, const std::string& message) const;

 private:
  bool ReadLine(std::string& line);  // the next line, whatever its ending; false at the end
  std::string_view Field(int column) const;
  template <typename T>
  T Parse(int column, const char* what) const;

  std::istream& in_;
  std::string source_;
  std::vector<std::string> header_;
  std::string text_;
  std::string cr_lines_;                    // the rest of a line read up to LF that held lone CRs
  std::size_t cr_next_ = std::string::npos;  // where its next line starts (npos: none left)
  std::vector<std::string_view> fields_;
  int line_ = 0;
  std::uint64_t bytes_read_ = 0;
};

// The file, open for reading, or an InputError "PATH: cannot open the file".
std::ifstream OpenForReading(const std::string& path);
// The whole file as text (small files: a shard's config, a log), or the same InputError.
std::string ReadWholeFile(const std::string& path);

}  // namespace anchorbench::io
