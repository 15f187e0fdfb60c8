#include "pdop_lines.hpp"

#include <optional>
#include <sstream>

#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/studies/navigation_lines.hpp"

namespace anchorbench::studies {
namespace {

// Every kind's columns; a line leaves the others empty.
constexpr const char* kPdopColumns =
    "kind,realization,anchor_id,n,t_s,pdop_closest_point,pdop_ls,pdop_nls,pdop_true,bias_aware_dop,"
    "dop4_closest_point,dop4_confidence,ls_error_m,nls_error_m,error_m,status,anchors,samples,below,worst_ratio,"
    "ideal_below,ideal_samples_precondition,ideal_below_precondition,ratios_below";
enum Column : int {
  kKind, kRealization, kAnchor, kN, kT, kPdop, kBiasAwareDop = kPdop + 4, kDop4ClosestPoint, kDop4Confidence,
  kLsError, kNlsError, kError, kStatus, kAnchors, kSamples, kBelow, kWorstRatio, kIdealBelow,
  kIdealSamplesPrecondition, kIdealBelowPrecondition, kRatiosBelow, kColumnCount
};

void WriteLine(std::ostringstream& text, const std::vector<std::string>& fields) {
  for (int c = 0; c < kColumnCount; ++c) {
    if (c > 0) text << ',';
    text << fields[static_cast<std::size_t>(c)];
  }
  text << '\n';
}

long Count(const io::CsvReader& csv, int column) {
  const long long value = csv.Integer64(column);
  if (value < 0) csv.Fail("column '" + csv.header(column) + "': a negative count");
  return static_cast<long>(value);
}

schema::PdopCheckpoint ReadCheckpoint(const io::CsvReader& csv) {
  schema::PdopCheckpoint c;
  c.realization = csv.Integer(kRealization);
  c.anchor_id = csv.Integer(kAnchor);
  c.n = csv.Integer(kN);
  c.t_s = csv.Number(kT);
  for (int m = 0; m < 4; ++m) c.pdop[static_cast<std::size_t>(m)] = csv.NumberOrNonFinite(kPdop + m);
  c.bias_aware_dop = csv.NumberOrNonFinite(kBiasAwareDop);
  c.dop4_closest_point = csv.NumberOrNonFinite(kDop4ClosestPoint);
  c.dop4_confidence = csv.NumberOrNonFinite(kDop4Confidence);
  c.ls_error_m = OptionalNumber(csv, kLsError);
  c.nls_error_m = OptionalNumber(csv, kNlsError);
  if (c.n < 1) csv.Fail("a checkpoint of fewer than one sample");
  return c;
}

schema::CertifiedOutcome ReadOutcome(const io::CsvReader& csv) {
  schema::CertifiedOutcome o;
  o.realization = csv.Integer(kRealization);
  o.anchor_id = csv.Integer(kAnchor);
  o.t_s = OptionalNumber(csv, kT);
  o.n = static_cast<int>(Count(csv, kN));
  o.error_m = OptionalNumber(csv, kError);
  o.status = std::string(csv.Text(kStatus));
  if (o.status.empty()) csv.Fail("an outcome without a status");
  return o;
}

void ReadStats(const io::CsvReader& csv, schema::PdopStudy& study) {
  study.anchors = static_cast<int>(Count(csv, kAnchors));
  schema::UnderestimateStats& s = study.stats;
  s.samples = Count(csv, kSamples);
  s.below = Count(csv, kBelow);
  s.worst_ratio = csv.Number(kWorstRatio);
  s.ideal_below = Count(csv, kIdealBelow);
  s.ideal_samples_precondition = Count(csv, kIdealSamplesPrecondition);
  s.ideal_below_precondition = Count(csv, kIdealBelowPrecondition);
  s.ratios_below = ParseBins(csv, kRatiosBelow);
  if (s.below > s.samples || s.ideal_below > s.samples || s.ideal_below_precondition > s.ideal_samples_precondition ||
      static_cast<long>(s.ratios_below.size()) != s.below) {
    csv.Fail("more samples below than samples, or a ratio for other than each sample below");
  }
}

}  // namespace

std::string PdopUnitText(const std::vector<schema::PdopStudy>& records) {
  std::ostringstream text;
  for (const schema::PdopStudy& study : records) {
    for (const schema::PdopCheckpoint& c : study.checkpoints) {
      std::vector<std::string> f(kColumnCount);
      f[kKind] = "checkpoint";
      f[kRealization] = std::to_string(c.realization);
      f[kAnchor] = std::to_string(c.anchor_id);
      f[kN] = std::to_string(c.n);
      f[kT] = io::FormatNumber(c.t_s);
      for (int m = 0; m < 4; ++m) f[static_cast<std::size_t>(kPdop + m)] = io::FormatNumber(c.pdop[static_cast<std::size_t>(m)]);
      f[kBiasAwareDop] = io::FormatNumber(c.bias_aware_dop);
      f[kDop4ClosestPoint] = io::FormatNumber(c.dop4_closest_point);
      f[kDop4Confidence] = io::FormatNumber(c.dop4_confidence);
      f[kLsError] = io::FormatOptional(c.ls_error_m);
      f[kNlsError] = io::FormatOptional(c.nls_error_m);
      WriteLine(text, f);
    }
    for (const schema::CertifiedOutcome& o : study.certified) {
      std::vector<std::string> f(kColumnCount);
      f[kKind] = "certified";
      f[kRealization] = std::to_string(o.realization);
      f[kAnchor] = std::to_string(o.anchor_id);
      f[kN] = std::to_string(o.n);
      f[kT] = io::FormatOptional(o.t_s);
      f[kError] = io::FormatOptional(o.error_m);
      f[kStatus] = o.status;
      WriteLine(text, f);
    }
    const schema::UnderestimateStats& s = study.stats;
    std::vector<std::string> f(kColumnCount);
    f[kKind] = "stats";
    f[kAnchors] = std::to_string(study.anchors);
    f[kSamples] = std::to_string(s.samples);
    f[kBelow] = std::to_string(s.below);
    f[kWorstRatio] = io::FormatNumber(s.worst_ratio);
    f[kIdealBelow] = std::to_string(s.ideal_below);
    f[kIdealSamplesPrecondition] = std::to_string(s.ideal_samples_precondition);
    f[kIdealBelowPrecondition] = std::to_string(s.ideal_below_precondition);
    f[kRatiosBelow] = BinsText(s.ratios_below);
    WriteLine(text, f);
  }
  return text.str();
}

std::vector<schema::PdopStudy> ReadPdopUnit(const std::string& text, const engine::UnitPlace& place, int realization) {
  std::istringstream in(std::string(kPdopColumns) + "\n" + text);
  io::CsvReader csv(in, place.file, static_cast<int>(place.line));  // the columns in the block header's place
  schema::PdopStudy study;
  bool whole = false;
  while (csv.Next()) {
    if (whole) csv.Fail("a line after the realization's statistics");
    const std::string_view kind = csv.Text(kKind);
    if (kind == "stats") {
      ReadStats(csv, study);
      whole = true;
      continue;
    }
    if (kind != "checkpoint" && kind != "certified") csv.Fail("column 'kind': '" + std::string(kind) + "' is not a kind of line");
    if (csv.Integer(kRealization) != realization) {
      csv.Fail("not a line of realization " + std::to_string(realization));
    }
    if (kind == "checkpoint") {
      study.checkpoints.push_back(ReadCheckpoint(csv));
    } else {
      study.certified.push_back(ReadOutcome(csv));
    }
  }
  if (!whole) {
    throw schema::InputError(place.where() + ": realization " + std::to_string(realization) +
                             ": no statistics line (a unit cut short)");
  }
  return {std::move(study)};
}

}  // namespace anchorbench::studies
