#pragma once
// The calibration's evaluations on disk, one CSV line each, appended and flushed as they finish:
// a killed calibration loses at most the evaluation it was computing, and a rerun takes the
// finished ones from the log instead of recomputing them.

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace anchorbench::studies {

// One evaluation: the parameter values as the experiment read them (text: exactly what --set
// passes), our value of each target cell (absent where nothing initialized) and the objective.
struct Evaluation {
  std::string stage;  // "hand", "global", "local", "profile"
  std::vector<std::string> values;
  std::vector<std::optional<double>> ours;
  double objective = 0.0;
};

// Columns: context,evaluation,stage,<parameter keys>,objective,<cell names>,checksum. `context` is
// a hash of what decides the cells besides the parameters (the experiment as resolved, the fit's
// seed and realizations): lines of another context are never reused. `checksum` is the FNV-1a
// fingerprint of the line before it: an edited line is refused, never taken.
class EvaluationLog {
 public:
  EvaluationLog(std::vector<std::string> keys, std::vector<std::string> cell_names, std::uint64_t context);

  // Takes the finished evaluations of `path` (a log of a killed run, or a finished calibration's
  // evaluations.csv) as known; returns how many matched this context. A torn last line (the
  // process was killed while writing it) is ignored, and so are a byte-order mark and CRLF line
  // ends. InputError naming the file: a header of other parameters or cells; and naming the line
  // (to cut): a cell or objective that is not a finite number >= 0, a line that does not match its
  // checksum, an evaluation repeated with other cells.
  int Reuse(const std::filesystem::path& path);

  // The cells of an evaluation at these values, if known.
  const std::vector<std::optional<double>>* Find(const std::vector<std::string>& values) const;

  // Appends to the file at `path` from now on (creating it with its header).
  void AppendTo(const std::filesystem::path& path);
  // Adds an evaluation to this run's; one just computed also goes to the file, flushed before
  // this returns.
  void Record(const Evaluation& evaluation, bool computed);

  const std::vector<Evaluation>& evaluations() const { return evaluations_; }  // this run's, in order
  std::string Header() const;
  std::string Line(std::size_t index) const;

 private:
  std::vector<std::string> keys_;
  std::vector<std::string> cell_names_;
  std::string context_;
  std::map<std::vector<std::string>, std::vector<std::optional<double>>> known_;
  std::vector<Evaluation> evaluations_;
  std::ofstream file_;
  std::filesystem::path path_;
};

}  // namespace anchorbench::studies
