#include "anchorbench/io/csv_reader.hpp"

#include <charconv>
#include <filesystem>
#include <iterator>
#include <cmath>

#include "anchorbench/io/format.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::io {
namespace {

std::string_view Trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

void Split(std::string_view line, std::vector<std::string_view>& fields) {
  fields.clear();
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(Trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
}

std::string_view Unquoted(std::string_view name) {
  if (name.size() >= 2 && name.front() == '"' && name.back() == '"') return Trim(name.substr(1, name.size() - 2));
  return name;
}

}  // namespace

std::ifstream OpenForReading(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) throw schema::InputError(path + ": is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw schema::InputError(path + ": cannot open the file");
  return in;
}

std::string ReadWholeFile(const std::string& path) {
  std::ifstream in = OpenForReading(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

bool CsvReader::ReadLine(std::string& line) {
  if (cr_next_ == std::string::npos) {
    if (!std::getline(in_, line)) return false;
    const std::size_t cr = line.find('\r');
    if (cr == std::string::npos || cr + 1 == line.size()) {  // LF or CRLF: the common case
      bytes_read_ += line.size() + 1;
      return true;
    }
    cr_lines_.assign(line, cr + 1);  // lone CRs: the rest are lines of their own
    cr_next_ = 0;
    line.resize(cr);
    bytes_read_ += cr + 1;
    return true;
  }
  const std::size_t cr = cr_lines_.find('\r', cr_next_);
  const std::size_t end = cr == std::string::npos ? cr_lines_.size() : cr;
  line.assign(cr_lines_, cr_next_, end - cr_next_);
  bytes_read_ += end - cr_next_ + 1;
  cr_next_ = cr == std::string::npos || cr + 1 == cr_lines_.size() ? std::string::npos : cr + 1;
  return true;
}

CsvReader::CsvReader(std::istream& in, std::string source, int header_line_number)
    : in_(in), source_(std::move(source)) {
  std::string header_line;
  if (!ReadLine(header_line)) throw schema::InputError(source_ + ":1: empty file, expected a header line");
  line_ = header_line_number;
  if (header_line.size() >= 3 && header_line.compare(0, 3, "\xEF\xBB\xBF") == 0) header_line.erase(0, 3);  // UTF-8 BOM
  Split(header_line, fields_);
  for (std::string_view name : fields_) header_.emplace_back(Unquoted(name));
  fields_.clear();
}

int CsvReader::OptionalColumn(std::initializer_list<std::string_view> names) const {
  for (std::string_view name : names) {
    for (std::size_t i = 0; i < header_.size(); ++i)
      if (header_[i] == name) return static_cast<int>(i);
  }
  return -1;
}

int CsvReader::Column(std::initializer_list<std::string_view> names) const {
  const int index = OptionalColumn(names);
  if (index >= 0) return index;
  std::string listed;
  for (std::string_view name : names) listed += (listed.empty() ? "'" : " or '") + std::string(name) + "'";
  throw schema::InputError(source_ + ":1: missing column " + listed);
}

void CsvReader::Fail(const std::string& message) const { FailAt(line_, message); }

void CsvReader::FailAt(int line, const std::string& message) const {
  throw schema::InputError(source_ + ":" + std::to_string(line) + ": " + message);
}

bool CsvReader::Next() {
  while (ReadLine(text_)) {
    ++line_;
    const std::string_view trimmed = Trim(text_);
    if (trimmed.empty() || trimmed.front() == '#') continue;
    Split(text_, fields_);
    if (fields_.size() != header_.size()) {
      Fail("expected " + std::to_string(header_.size()) + " fields as in the header, found " +
           std::to_string(fields_.size()));
    }
    return true;
  }
  return false;
}

std::string_view CsvReader::Field(int column) const { return fields_[static_cast<std::size_t>(column)]; }

bool CsvReader::Empty(int column) const { return Field(column).empty(); }

template <typename T>
T CsvReader::Parse(int column, const char* what) const {
  const std::string_view field = Field(column);
  T value{};
  const char* end = field.data() + field.size();
  const auto [ptr, ec] = std::from_chars(field.data(), end, value);
  if (field.empty() || ec != std::errc() || ptr != end) {
    Fail("column '" + Printable(header_[static_cast<std::size_t>(column)]) + "': '" + Printable(field) + "' is not " +
         what);
  }
  return value;
}

double CsvReader::Number(int column) const {
  const double value = Parse<double>(column, "a number");
  if (!std::isfinite(value)) {
    Fail("column '" + Printable(header_[static_cast<std::size_t>(column)]) + "': '" + Printable(Field(column)) +
         "' is not finite");
  }
  return value;
}

double CsvReader::NumberOrNonFinite(int column) const { return Parse<double>(column, "a number"); }

int CsvReader::Integer(int column) const { return Parse<int>(column, "an integer"); }

long long CsvReader::Integer64(int column) const { return Parse<long long>(column, "an integer"); }

}  // namespace anchorbench::io
