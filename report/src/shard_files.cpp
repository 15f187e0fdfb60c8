#include "anchorbench/report/shard_files.hpp"

#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/io/input_error.hpp"

namespace anchorbench::report {
namespace {

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace

void WriteShardCsv(std::ostream& out, const ShardInfo& info) {
  out << "shard,of,units,config_name,config_hash,revision\n"
      << info.shard.index << ',' << info.shard.count << ',' << info.units << ',' << info.config_name << ','
      << info.config_hash << ',' << info.revision << '\n';
}

ShardInfo ReadShardCsv(const std::string& path) {
  std::ifstream in = io::OpenForReading(path);
  io::CsvReader csv(in, path);
  if (!csv.Next()) csv.Fail("no shard line");
  ShardInfo info;
  info.shard.index = csv.Integer(csv.Column({"shard"}));
  info.shard.count = csv.Integer(csv.Column({"of"}));
  info.units = csv.Integer(csv.Column({"units"}));
  info.config_name = std::string(csv.Text(csv.Column({"config_name"})));
  info.config_hash = std::string(csv.Text(csv.Column({"config_hash"})));
  info.revision = std::string(csv.Text(csv.Column({"revision"})));
  if (info.shard.count < 1 || info.shard.index < 0 || info.shard.index >= info.shard.count) {
    csv.Fail("shard " + std::to_string(info.shard.index) + " of " + std::to_string(info.shard.count) + " is not a shard");
  }
  return info;
}

void WriteComputeCsv(std::ostream& out, const std::vector<runner::Attempt>& attempts) {
  out << "compute_s\n";
  for (const runner::Attempt& a : attempts) out << io::FormatNumber(a.compute_s) << '\n';
}

AttemptsFile ParseAttempts(const std::string& text, const std::string& source,
                           const std::vector<runner::RowConfig>& rows, std::istream* compute_in,
                           const std::string& compute_source) {
  std::map<std::string, int, std::less<>> row_index;
  for (std::size_t r = 0; r < rows.size(); ++r) row_index[rows[r].name] = static_cast<int>(r);
  AttemptsFile file;
  file.lines = Lines(text);
  if (file.lines.empty()) throw io::InputError(source + ": empty file, expected attempts.csv's header");
  file.header = file.lines.front();
  file.lines.erase(file.lines.begin());

  std::istringstream in(text);
  io::CsvReader csv(in, source);
  const int row = csv.Column({"row"}), realization = csv.Column({"realization"}), anchor = csv.Column({"anchor_id"});
  const int method = csv.Column({"method"}), initialized = csv.Column({"initialized"}), t_init = csv.Column({"t_init"});
  const int error = csv.Column({"err_m"}), nees = csv.Column({"nees_pos"});
  // compute_s: a column of its own file, or the last column of this one (a chunk).
  std::optional<io::CsvReader> compute;
  if (compute_in) compute.emplace(*compute_in, compute_source);
  const int compute_s = compute ? compute->Column({"compute_s"}) : csv.Column({"compute_s"});
  if (!compute) {
    const std::size_t cut = file.header.rfind(',');
    if (cut == std::string::npos || file.header.substr(cut + 1) != "compute_s") {
      throw io::InputError(source + ":1: compute_s must be the last column");
    }
    file.header.erase(cut);
  }
  std::size_t index = 0;
  while (csv.Next()) {
    runner::Attempt a;
    const auto found = row_index.find(csv.Text(row));
    if (found == row_index.end()) csv.Fail("row '" + std::string(csv.Text(row)) + "' is not a row of the config");
    a.row = found->second;
    a.realization = csv.Integer(realization);
    a.anchor_id = csv.Integer(anchor);
    a.method = std::string(csv.Text(method));
    a.initialized = csv.Integer(initialized) == 1;
    if (a.initialized) {
      a.t_init_s = csv.Number(t_init);
      a.evaluation.emplace();
      a.evaluation->error_m = csv.Number(error);
      if (!csv.Empty(nees)) a.evaluation->nees_position = csv.Number(nees);
    }
    if (compute) {
      if (!compute->Next()) compute->Fail("fewer lines than " + source);
      a.compute_s = compute->Number(compute_s);
    } else {
      a.compute_s = csv.Number(compute_s);
      if (index < file.lines.size()) file.lines[index].erase(file.lines[index].rfind(','));
    }
    file.attempts.push_back(std::move(a));
    ++index;
  }
  if (compute && compute->Next()) compute->Fail("more lines than " + source);
  if (file.attempts.size() != file.lines.size()) {
    throw io::InputError(source + ": blank or comment lines; expected attempts as written");
  }
  return file;
}

AttemptsFile ReadAttemptsCsv(const std::string& path, const std::string& compute_path,
                             const std::vector<runner::RowConfig>& rows) {
  std::ifstream compute_in = io::OpenForReading(compute_path);
  return ParseAttempts(io::ReadWholeFile(path), path, rows, &compute_in, compute_path);
}

}  // namespace anchorbench::report
