#include "anchorbench/studies/evaluation_log.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/io/hash.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::studies {

EvaluationLog::EvaluationLog(std::vector<std::string> keys, std::vector<std::string> cell_names, std::uint64_t context)
    : keys_(std::move(keys)), cell_names_(std::move(cell_names)) {
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(context));
  context_ = text;
}

std::string EvaluationLog::Header() const {
  std::string header = "context,evaluation,stage";
  for (const std::string& key : keys_) header.append(",").append(key);
  header += ",objective";
  for (const std::string& name : cell_names_) header.append(",").append(name);
  return header + ",checksum";
}

std::string EvaluationLog::Line(std::size_t index) const {
  const Evaluation& e = evaluations_[index];
  std::string line = context_ + "," + std::to_string(index) + "," + e.stage;
  for (const std::string& value : e.values) line.append(",").append(value);
  line.append(",").append(io::FormatNumber(e.objective));
  for (const std::optional<double>& ours : e.ours) line.append(",").append(io::FormatOptional(ours));
  return line + "," + io::Fingerprint(line);
}

namespace {

// The length of the text up to its last newline: what a process killed mid-line left whole.
std::size_t WholeLines(const std::string& text) {
  const std::size_t end = text.find_last_of('\n');
  return end == std::string::npos ? 0 : end + 1;
}

// A log's text as this program writes it: no byte-order mark, LF line ends, no torn last line.
std::string Normalized(std::string text) {
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  text.resize(WholeLines(text));
  std::erase(text, '\r');
  return text;
}

// A cell or objective as the log holds it: a finite number >= 0 (every Table I cell is), or empty.
std::optional<double> CellValue(const io::CsvReader& csv, int column, const std::string& cut) {
  if (csv.Empty(column)) return std::nullopt;
  const double value = csv.NumberOrNonFinite(column);
  if (!std::isfinite(value) || value < 0.0) {
    csv.Fail("column '" + csv.header(column) + "': " + io::FormatNumber(value) + " is not a finite number >= 0" + cut);
  }
  return value;
}

}  // namespace

int EvaluationLog::Reuse(const std::filesystem::path& path) {
  const std::string text = Normalized(io::ReadWholeFile(path.string()));
  std::istringstream lines(text);
  std::string header;
  std::getline(lines, header);
  if (header != Header()) {
    throw schema::InputError(path.string() + ":1: the log is of other parameters or cells (its header is not '" +
                         Header() + "')");
  }
  lines.seekg(0);
  io::CsvReader csv(lines, path.string());
  const int context = csv.Column({"context"});
  const int first_key = csv.Column({"stage"}) + 1;
  const int objective = first_key + static_cast<int>(keys_.size());
  const int first_cell = objective + 1;
  const int checksum = csv.Column({"checksum"});
  std::map<std::vector<std::string>, int> line_of;
  int reused = 0;
  while (csv.Next()) {
    const std::string cut = "; cut line " + std::to_string(csv.line()) + " to have it computed again";
    // The line as written: its fields, checked, then its checksum (an edit, a torn or merged line).
    std::string_view line = csv.record_text();
    line = line.substr(0, line.rfind(','));
    if (!CellValue(csv, objective, cut)) csv.Fail("no objective" + cut);
    std::vector<std::optional<double>> ours;
    for (std::size_t c = 0; c < cell_names_.size(); ++c) ours.push_back(CellValue(csv, first_cell + static_cast<int>(c), cut));
    if (csv.Text(checksum) != io::Fingerprint(line)) csv.Fail("the line does not match its checksum (edited?)" + cut);
    if (csv.Text(context) != context_) continue;
    std::vector<std::string> values;
    for (std::size_t k = 0; k < keys_.size(); ++k) values.emplace_back(csv.Text(first_key + static_cast<int>(k)));
    const auto [known, fresh] = known_.emplace(values, ours);
    if (!fresh && known->second != ours) {
      csv.Fail("the evaluation at these values has other cells than line " + std::to_string(line_of[values]) +
               " (one of the two edited?)" + cut);
    }
    line_of.emplace(values, csv.line());
    ++reused;
  }
  return reused;
}

const std::vector<std::optional<double>>* EvaluationLog::Find(const std::vector<std::string>& values) const {
  const auto found = known_.find(values);
  return found == known_.end() ? nullptr : &found->second;
}

void EvaluationLog::AppendTo(const std::filesystem::path& path) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  const bool fresh = error || size == 0;  // absent, empty, or not a regular file (a device)
  if (!fresh) {  // cut a torn last line, so the next record starts a line of its own
    const std::string text = io::ReadWholeFile(path.string());
    if (WholeLines(text) != text.size()) std::filesystem::resize_file(path, WholeLines(text), error);
  }
  file_.open(path, std::ios::app);
  if (!file_) throw schema::InputError(path.string() + ": cannot open the evaluation log for appending: " + std::strerror(errno));
  path_ = path;
  if (fresh) file_ << Header() << '\n' << std::flush;
  if (!file_) throw schema::InputError(path.string() + ": writing the evaluation log failed: " + std::strerror(errno));
}

void EvaluationLog::Record(const Evaluation& evaluation, bool computed) {
  evaluations_.push_back(evaluation);
  known_[evaluation.values] = evaluation.ours;
  if (!computed || !file_.is_open()) return;
  file_ << Line(evaluations_.size() - 1) << '\n' << std::flush;
  if (!file_) throw schema::InputError(path_.string() + ": writing the evaluation log failed: " + std::strerror(errno));
}

}  // namespace anchorbench::studies
