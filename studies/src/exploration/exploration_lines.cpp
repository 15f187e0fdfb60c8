#include "anchorbench/studies/exploration_lines.hpp"

#include <sstream>

#include "anchorbench/studies/navigation_lines.hpp"
#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::studies {
namespace {

constexpr const char* kExplorationColumns =
    "row,realization,policy,anchors,certified,beyond_accuracy,max_error_m,t_all_certified_s,duration_s,distance_m,"
    "detours,navigation_rmse_m,navigation_error_by_bin_m";

// What no run writes: refused even where a checksum was made to fit.
void Check(const io::CsvReader& csv, const ExplorationRecord& r) {
  if (r.anchors < 0 || r.certified < 0 || r.beyond_accuracy < 0 || r.detours < 0) csv.Fail("a negative count");
  if (r.certified > r.anchors || r.beyond_accuracy > r.certified) {
    csv.Fail("more certified than anchors, or more beyond D than certified");
  }
  if (!(r.max_error_m >= 0.0) || !(r.duration_s >= 0.0) || !(r.distance_m >= 0.0)) {
    csv.Fail("an error, duration or distance that is negative");
  }
}

}  // namespace

std::string ExplorationUnitText(const std::vector<ExplorationRecord>& records) {
  std::ostringstream text;
  for (const ExplorationRecord& r : records) {
    text << r.row << ',' << r.realization << ',' << r.policy << ',' << r.anchors << ',' << r.certified << ','
         << r.beyond_accuracy << ',' << io::FormatNumber(r.max_error_m) << ',' << io::FormatNumber(r.t_all_certified_s)
         << ',' << io::FormatNumber(r.duration_s) << ',' << io::FormatNumber(r.distance_m) << ',' << r.detours << ','
         << io::FormatNumber(r.navigation_rmse_m) << ',' << BinsText(r.navigation_error_by_bin_m) << '\n';
  }
  return text.str();
}

std::vector<ExplorationRecord> ReadExplorationUnit(const std::string& text, const engine::UnitPlace& place, int row,
                                                   int realization, const std::vector<std::string>& policies) {
  std::istringstream in(std::string(kExplorationColumns) + "\n" + text);
  io::CsvReader csv(in, place.file, static_cast<int>(place.line));  // the columns in the block header's place
  const int row_column = csv.Column({"row"}), realization_column = csv.Column({"realization"});
  const int policy = csv.Column({"policy"}), anchors = csv.Column({"anchors"}), certified = csv.Column({"certified"});
  const int beyond = csv.Column({"beyond_accuracy"}), max_error = csv.Column({"max_error_m"});
  const int t_all = csv.Column({"t_all_certified_s"}), duration = csv.Column({"duration_s"});
  const int distance = csv.Column({"distance_m"}), detours = csv.Column({"detours"});
  const int rmse = csv.Column({"navigation_rmse_m"}), bins = csv.Column({"navigation_error_by_bin_m"});
  std::vector<ExplorationRecord> records;
  while (csv.Next()) {
    ExplorationRecord r;
    r.row = csv.Integer(row_column);
    r.realization = csv.Integer(realization_column);
    r.policy = std::string(csv.Text(policy));
    const std::size_t k = records.size();
    if (r.row != row || r.realization != realization || k >= policies.size() || r.policy != policies[k]) {
      csv.Fail("not the next record of row " + std::to_string(row) + ", realization " + std::to_string(realization));
    }
    r.anchors = csv.Integer(anchors);
    r.certified = csv.Integer(certified);
    r.beyond_accuracy = csv.Integer(beyond);
    r.max_error_m = csv.Number(max_error);
    r.t_all_certified_s = csv.Number(t_all);
    r.duration_s = csv.Number(duration);
    r.distance_m = csv.Number(distance);
    r.detours = csv.Integer(detours);
    r.navigation_rmse_m = csv.Number(rmse);
    r.navigation_error_by_bin_m = ParseBins(csv, bins);
    Check(csv, r);
    records.push_back(std::move(r));
  }
  if (records.size() != policies.size()) {
    throw schema::InputError(place.where() + ": row " + std::to_string(row) + ", realization " +
                             std::to_string(realization) + ": " + std::to_string(records.size()) + " records, not one per policy");
  }
  return records;
}

}  // namespace anchorbench::studies
