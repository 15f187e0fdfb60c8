#include "anchorbench/studies/navigation_lines.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

#include "anchorbench/io/format.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::studies {
namespace {

// What no run writes: refused even where a checksum was made to fit.
void CheckOutcome(const io::CsvReader& csv, const nav::NavigationOutcome& o) {
  if (!(o.rmse_m >= 0.0) || !(o.final_error_m >= 0.0)) csv.Fail("an error that is negative or not a number");
  if (!(o.fix_share >= 0.0 && o.fix_share <= 1.0)) csv.Fail("a fix share outside [0, 1]");
  if (o.ranges_used < 0 || o.ranges_gated < 0) csv.Fail("a negative count of ranges");
  for (const double e : o.error_by_bin_m) {
    if (!(e >= 0.0) && !std::isnan(e)) csv.Fail("a binned error that is negative or infinite");
  }
}

}  // namespace

std::string BinsText(const std::vector<double>& bins) {
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
      csv.Fail("column '" + csv.header(column) + "': '" + std::string(item) + "' is not a number");
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

namespace {

}  // namespace

std::string NavigationRecordFields(const NavigationRecord& r) {
  const nav::NavigationOutcome& o = r.outcome;
  std::ostringstream fields;
  fields << r.row << ',' << r.realization << ',' << r.method << ',' << io::FormatNumber(o.rmse_m) << ','
         << io::FormatNumber(o.final_error_m) << ',' << io::FormatOptional(o.t_first_anchor_s) << ','
         << io::FormatOptional(o.t_kth_anchor_s) << ',' << io::FormatNumber(o.fix_share) << ',' << o.ranges_used << ','
         << o.ranges_gated << ',' << BinsText(o.error_by_bin_m);
  return fields.str();
}

NavigationRecordReader::NavigationRecordReader(const io::CsvReader& csv)
    : row_(csv.Column({"row"})),
      realization_(csv.Column({"realization"})),
      method_(csv.Column({"method"})),
      rmse_(csv.Column({"rmse_m"})),
      final_error_(csv.Column({"final_error_m"})),
      t_first_(csv.Column({"t_first_anchor_s"})),
      t_kth_(csv.Column({"t_kth_anchor_s"})),
      fix_(csv.Column({"fix_share"})),
      used_(csv.Column({"ranges_used"})),
      gated_(csv.Column({"ranges_gated"})),
      bins_(csv.Column({"error_by_bin_m"})) {}

NavigationRecord NavigationRecordReader::Read(const io::CsvReader& csv) const {
  NavigationRecord r;
  r.row = csv.Integer(row_);
  r.realization = csv.Integer(realization_);
  r.method = std::string(csv.Text(method_));
  r.outcome.rmse_m = csv.Number(rmse_);
  r.outcome.final_error_m = csv.Number(final_error_);
  r.outcome.t_first_anchor_s = OptionalNumber(csv, t_first_);
  r.outcome.t_kth_anchor_s = OptionalNumber(csv, t_kth_);
  r.outcome.fix_share = csv.Number(fix_);
  r.outcome.ranges_used = csv.Integer64(used_);
  r.outcome.ranges_gated = csv.Integer64(gated_);
  r.outcome.error_by_bin_m = ParseBins(csv, bins_);
  CheckOutcome(csv, r.outcome);
  return r;
}

std::string NavigationUnitText(const std::vector<NavigationRecord>& records) {
  std::string text;
  for (const NavigationRecord& r : records) text.append(NavigationRecordFields(r)).push_back('\n');
  return text;
}

std::vector<NavigationRecord> ReadNavigationUnit(const std::string& text, const engine::UnitPlace& place, int row,
                                                 int realization, const std::vector<std::string>& methods) {
  std::istringstream in(std::string(kNavigationRecordColumns) + "\n" + text);
  io::CsvReader csv(in, place.file, static_cast<int>(place.line));  // the columns in the block header's place
  const NavigationRecordReader reader(csv);
  std::vector<NavigationRecord> records;
  while (csv.Next()) {
    NavigationRecord r = reader.Read(csv);
    const std::size_t k = records.size();
    if (r.row != row || r.realization != realization || k >= methods.size() || r.method != methods[k]) {
      csv.Fail("not the next record of row " + std::to_string(row) + ", realization " + std::to_string(realization));
    }
    records.push_back(std::move(r));
  }
  if (records.size() != methods.size()) {
    throw schema::InputError(place.where() + ": row " + std::to_string(row) + ", realization " + std::to_string(realization) +
                             ": " + std::to_string(records.size()) + " records, not one per method");
  }
  return records;
}

}  // namespace anchorbench::studies
