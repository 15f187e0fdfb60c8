#include "anchorbench/report/attempts_file.hpp"

#include <map>
#include <sstream>

#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::report {

AttemptsFile ParseAttempts(const std::string& text, const std::string& source,
                           const std::vector<schema::RowConfig>& rows) {
  std::map<std::string, int, std::less<>> row_index;
  for (std::size_t r = 0; r < rows.size(); ++r) row_index[rows[r].name] = static_cast<int>(r);
  AttemptsFile file;
  std::istringstream in(text);
  io::CsvReader csv(in, source);  // one pass: each record's line is kept as the reader meets it
  const int row = csv.Column({"row"}), realization = csv.Column({"realization"}), anchor = csv.Column({"anchor_id"});
  const int method = csv.Column({"method"}), initialized = csv.Column({"initialized"}), t_init = csv.Column({"t_init"});
  const int error = csv.Column({"err_m"}), nees = csv.Column({"nees_pos"});
  const int t_oracle = csv.Column({"t_oracle"}), latency = csv.Column({"latency"});
  const int compute_s = csv.Column({"compute_s"});
  if (compute_s != csv.columns() - 1 || compute_s == 0) {
    throw schema::InputError(source + ":1: compute_s must be the last column");
  }
  while (csv.Next()) {
    schema::Attempt a;
    const auto found = row_index.find(csv.Text(row));
    if (found == row_index.end()) csv.Fail("row '" + std::string(csv.Text(row)) + "' is not a row of the config");
    a.row = found->second;
    a.realization = csv.Integer(realization);
    a.anchor_id = csv.Integer(anchor);
    a.method = std::string(csv.Text(method));
    a.initialized = csv.Integer(initialized) == 1;
    if (a.initialized || !csv.Empty(t_oracle)) a.evaluation.emplace();
    if (a.initialized) {
      a.t_init_s = csv.Number(t_init);
      a.evaluation->error_m = csv.Number(error);
      if (!csv.Empty(nees)) a.evaluation->nees_position = csv.Number(nees);
      if (!csv.Empty(latency)) a.evaluation->latency_ratio = csv.Number(latency);
    }
    if (!csv.Empty(t_oracle)) a.evaluation->t_oracle_s = csv.Number(t_oracle);
    a.compute_s = csv.Number(compute_s);
    // The line as written, without compute_s (the last field: the header has more than one).
    std::string_view line = csv.record_text();
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    file.lines.append(line.substr(0, line.rfind(','))).push_back('\n');
    file.attempts.push_back(std::move(a));
  }
  return file;
}

}  // namespace anchorbench::report
