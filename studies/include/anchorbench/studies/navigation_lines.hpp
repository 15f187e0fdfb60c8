#pragma once
// A navigation study's records as CSV lines at round-trip precision, and back: what navigate's
// journal (record_journal.hpp) and its shards' records.csv hold, so that records read back give the
// uninterrupted, unsharded run's bytes.

#include <optional>
#include <string>
#include <vector>

#include "anchorbench/engine/record_journal.hpp"
#include "anchorbench/studies/navigation.hpp"
#include "anchorbench/io/csv_reader.hpp"

namespace anchorbench::studies {

// The columns of a record line.
inline constexpr const char* kNavigationRecordColumns =
    "row,realization,method,rmse_m,final_error_m,t_first_anchor_s,t_kth_anchor_s,fix_share,ranges_used,ranges_gated,"
    "error_by_bin_m";

// Binned errors as one field: ';'-separated at round-trip precision, "nan" for a bin without a
// sample; and back from `column` of the reader's line (its error names the line).
std::string BinsText(const std::vector<double>& bins);
std::vector<double> ParseBins(const io::CsvReader& csv, int column);
// A number, or none where `column` is empty (io::FormatOptional's cell).
std::optional<double> OptionalNumber(const io::CsvReader& csv, int column);

// One record's fields, without a line end.
std::string NavigationRecordFields(const NavigationRecord& record);

// The records of a CSV with kNavigationRecordColumns (and maybe more) in its header, one per
// Next(); refuses (the reader's error: file and line) a malformed line or a value no run writes.
class NavigationRecordReader {
 public:
  explicit NavigationRecordReader(const io::CsvReader& csv);
  NavigationRecord Read(const io::CsvReader& csv) const;

 private:
  int row_, realization_, method_, rmse_, final_error_, t_first_, t_kth_, fix_, used_, gated_, bins_;
};

// A realization's records as the lines of a journal's or a shard's unit, and back: refuses
// (InputError naming `place`'s file and the line) lines that are not `row` and `realization`'s
// records of `methods`, each once, in order.
std::string NavigationUnitText(const std::vector<NavigationRecord>& records);
std::vector<NavigationRecord> ReadNavigationUnit(const std::string& text, const engine::UnitPlace& place, int row,
                                                 int realization, const std::vector<std::string>& methods);

}  // namespace anchorbench::studies
