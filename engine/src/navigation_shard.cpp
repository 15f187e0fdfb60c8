#include "anchorbench/engine/navigation_shard.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/io/hash.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::engine {
namespace {

constexpr const char* kHeader =
    "row,realization,method,rmse_m,final_error_m,t_first_anchor_s,t_kth_anchor_s,fix_share,ranges_used,ranges_gated,"
    "error_by_bin_m,checksum";

// A line's checksum binds its fields to the run (the plan's identity): an edited value, a torn
// line or a line of another run's shard does not match.
std::string Checksum(const std::string& plan, std::string_view fields) {
  std::string text = plan;
  text.append("\n").append(fields);
  return io::Fingerprint(text);
}

// What no run writes: refused even where a checksum was made to fit.
void CheckOutcome(const io::CsvReader& csv, const nav::NavigationOutcome& o) {
  if (!(o.rmse_m >= 0.0) || !(o.final_error_m >= 0.0)) csv.Fail("an error that is negative or not a number");
  if (!(o.fix_share >= 0.0 && o.fix_share <= 1.0)) csv.Fail("a fix share outside [0, 1]");
  if (o.ranges_used < 0 || o.ranges_gated < 0) csv.Fail("a negative count of ranges");
  for (const double e : o.error_by_bin_m) {
    if (!(e >= 0.0) && !std::isnan(e)) csv.Fail("a binned error that is negative or infinite");
  }
}

std::string Bins(const std::vector<double>& bins) {  // ';'-separated, "nan" for a gap
  std::string text;
  for (double e : bins) {
    if (!text.empty()) text += ';';
    text += io::FormatNumber(e);
  }
  return text;
}

std::vector<double> ParseBins(const io::CsvReader& csv, int column) {
  std::vector<double> bins;
  const std::string_view text = csv.Text(column);
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = std::min(text.find(';', start), text.size());
    const std::string_view item = text.substr(start, end - start);
    double value = 0.0;
    if (item == "nan") {
      value = std::numeric_limits<double>::quiet_NaN();
    } else if (const auto [ptr, ec] = std::from_chars(item.data(), item.data() + item.size(), value);
               ec != std::errc() || ptr != item.data() + item.size()) {
      csv.Fail("column 'error_by_bin_m': '" + std::string(item) + "' is not a number");
    }
    bins.push_back(value);
    start = end + 1;
  }
  return bins;
}

std::optional<double> OptionalNumber(const io::CsvReader& csv, int column) {
  if (csv.Empty(column)) return std::nullopt;
  return csv.Number(column);
}

}  // namespace

void WriteNavigationShard(const std::function<void(const std::string&, const std::string&)>& write,
                          const ShardInfo& info, const ShardInputs& inputs,
                          const std::vector<NavigationRecord>& records) {
  std::ostringstream csv;
  csv << kHeader << '\n';
  for (const NavigationRecord& r : records) {
    const nav::NavigationOutcome& o = r.outcome;
    std::ostringstream fields;
    fields << r.row << ',' << r.realization << ',' << r.method << ',' << io::FormatNumber(o.rmse_m) << ','
           << io::FormatNumber(o.final_error_m) << ',' << io::FormatOptional(o.t_first_anchor_s) << ','
           << io::FormatOptional(o.t_kth_anchor_s) << ',' << io::FormatNumber(o.fix_share) << ',' << o.ranges_used
           << ',' << o.ranges_gated << ',' << Bins(o.error_by_bin_m);
    csv << fields.str() << ',' << Checksum(info.plan, fields.str()) << '\n';
  }
  write(kNavigationRecordsFile, csv.str());
  WriteShardIdentity(write, info, inputs);
}

std::vector<NavigationRecord> ReadNavigationShards(const std::vector<std::filesystem::path>& folders,
                                                   const std::vector<ShardInfo>& infos,
                                                   const schema::ExperimentConfig& config) {
  const std::vector<schema::RowConfig> row_configs = schema::RowsOf(config);
  const int rows = static_cast<int>(row_configs.size());
  const int units = rows * config.realizations;
  std::map<int, std::vector<NavigationRecord>> by_unit;
  for (std::size_t s = 0; s < folders.size(); ++s) {
    const std::string path = (folders[s] / kNavigationRecordsFile).string();
    std::ifstream in = io::OpenForReading(path);
    io::CsvReader csv(in, path);
    const int row = csv.Column({"row"}), realization = csv.Column({"realization"}), method = csv.Column({"method"}),
              rmse = csv.Column({"rmse_m"}), final_error = csv.Column({"final_error_m"}),
              t_first = csv.Column({"t_first_anchor_s"}), t_kth = csv.Column({"t_kth_anchor_s"}),
              fix = csv.Column({"fix_share"}), used = csv.Column({"ranges_used"}), gated = csv.Column({"ranges_gated"}),
              bins = csv.Column({"error_by_bin_m"}), checksum = csv.Column({"checksum"});
    while (csv.Next()) {
      std::string_view fields = csv.record_text();
      fields = fields.substr(0, fields.rfind(','));
      if (csv.Text(checksum) != Checksum(infos[s].plan, fields)) {
        csv.Fail("the line does not match its checksum (edited after the run, or another run's?)");
      }
      NavigationRecord r;
      r.row = csv.Integer(row);
      r.realization = csv.Integer(realization);
      const int unit = r.row * config.realizations + r.realization;
      if (r.row < 0 || r.row >= rows || r.realization < 0 || r.realization >= config.realizations ||
          !infos[s].shard.Holds(unit)) {
        csv.Fail("row " + std::to_string(r.row) + ", realization " + std::to_string(r.realization) +
                 " is not a unit of this shard (edited after the run?)");
      }
      r.method = std::string(csv.Text(method));
      r.outcome.rmse_m = csv.Number(rmse);
      r.outcome.final_error_m = csv.Number(final_error);
      r.outcome.t_first_anchor_s = OptionalNumber(csv, t_first);
      r.outcome.t_kth_anchor_s = OptionalNumber(csv, t_kth);
      r.outcome.fix_share = csv.Number(fix);
      r.outcome.ranges_used = csv.Integer64(used);
      r.outcome.ranges_gated = csv.Integer64(gated);
      r.outcome.error_by_bin_m = ParseBins(csv, bins);
      CheckOutcome(csv, r.outcome);
      by_unit[unit].push_back(std::move(r));
    }
  }
  std::vector<NavigationRecord> records;
  for (int unit = 0; unit < units; ++unit) {
    const auto found = by_unit.find(unit);
    std::vector<std::string> methods;
    if (found != by_unit.end()) {
      for (const NavigationRecord& r : found->second) methods.push_back(r.method);
    }
    if (methods != NavigationMethods(row_configs[static_cast<std::size_t>(unit / config.realizations)])) {
      throw schema::InputError("row " + std::to_string(unit / config.realizations) + ", realization " +
                               std::to_string(unit % config.realizations) + ": the shards' " + kNavigationRecordsFile +
                               " do not hold each of its methods once, in order (edited after the run?)");
    }
    for (NavigationRecord& r : found->second) records.push_back(std::move(r));
  }
  return records;
}

}  // namespace anchorbench::engine
