#include "anchorbench/calibrate/evaluation_log.hpp"

#include <cstdio>
#include <sstream>

#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/io/input_error.hpp"

namespace anchorbench::calibrate {

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
  return header;
}

std::string EvaluationLog::Line(std::size_t index) const {
  const Evaluation& e = evaluations_[index];
  std::string line = context_ + "," + std::to_string(index) + "," + e.stage;
  for (const std::string& value : e.values) line.append(",").append(value);
  line.append(",").append(io::FormatNumber(e.objective));
  for (const std::optional<double>& ours : e.ours) line.append(",").append(io::FormatOptional(ours));
  return line;
}

namespace {

// The length of the text up to its last newline: what a process killed mid-line left whole.
std::size_t WholeLines(const std::string& text) {
  const std::size_t end = text.find_last_of('\n');
  return end == std::string::npos ? 0 : end + 1;
}

}  // namespace

int EvaluationLog::Reuse(const std::filesystem::path& path) {
  std::string text = io::ReadWholeFile(path.string());
  text.resize(WholeLines(text));  // a torn last line goes
  std::istringstream lines(text);
  std::string header;
  std::getline(lines, header);
  if (header != Header()) {
    throw io::InputError(path.string() + ":1: the log is of other parameters or cells (its header is not '" +
                         Header() + "')");
  }
  lines.seekg(0);
  io::CsvReader csv(lines, path.string());
  const int context = csv.Column({"context"});
  const int first_key = csv.Column({"stage"}) + 1;
  const int first_cell = first_key + static_cast<int>(keys_.size()) + 1;
  int reused = 0;
  while (csv.Next()) {
    if (csv.Text(context) != context_) continue;
    std::vector<std::string> values;
    for (std::size_t k = 0; k < keys_.size(); ++k) values.emplace_back(csv.Text(first_key + static_cast<int>(k)));
    std::vector<std::optional<double>> ours;
    for (std::size_t c = 0; c < cell_names_.size(); ++c) {
      const int column = first_cell + static_cast<int>(c);
      ours.push_back(csv.Empty(column) ? std::nullopt : std::optional<double>(csv.Number(column)));
    }
    known_[values] = std::move(ours);
    ++reused;
  }
  return reused;
}

const std::vector<std::optional<double>>* EvaluationLog::Find(const std::vector<std::string>& values) const {
  const auto found = known_.find(values);
  return found == known_.end() ? nullptr : &found->second;
}

void EvaluationLog::AppendTo(const std::filesystem::path& path) {
  const bool fresh = !std::filesystem::exists(path) || std::filesystem::file_size(path) == 0;
  if (!fresh) {  // cut a torn last line, so the next record starts a line of its own
    const std::string text = io::ReadWholeFile(path.string());
    if (WholeLines(text) != text.size()) std::filesystem::resize_file(path, WholeLines(text));
  }
  file_.open(path, std::ios::app);
  if (!file_) throw io::InputError(path.string() + ": cannot open the evaluation log for appending");
  path_ = path;
  if (fresh || std::filesystem::file_size(path) == 0) file_ << Header() << '\n' << std::flush;
}

void EvaluationLog::Record(const Evaluation& evaluation, bool computed) {
  evaluations_.push_back(evaluation);
  known_[evaluation.values] = evaluation.ours;
  if (!computed || !file_.is_open()) return;
  file_ << Line(evaluations_.size() - 1) << '\n' << std::flush;
  if (!file_) throw io::InputError(path_.string() + ": writing the evaluation log failed");
}

}  // namespace anchorbench::calibrate
