#include "anchorbench/engine/chunk.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <functional>

#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/io/hash.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/report/run_outputs.hpp"
#include "anchorbench/report/attempts_file.hpp"
#include "anchorbench/engine/monte_carlo.hpp"

namespace anchorbench::engine {
namespace {

// The attempts a run writes for one unit: one per anchor and trigger.
std::size_t AttemptsPerUnit(const schema::RowConfig& row) {
  return static_cast<std::size_t>(row.scenario.NumAnchors()) * row.estimator.triggers.size();
}

}  // namespace

ChunkResult ComputeChunk(const Plan& plan, int chunk, const registry::Components& components,
                         std::vector<estimator::RangeSample>& samples, const StopFlag* stop) {
  const ChunkSpan& span = plan.chunks()[static_cast<std::size_t>(chunk)];
  const schema::ExperimentConfig& config = plan.experiments()[static_cast<std::size_t>(span.experiment)];
  const std::vector<schema::RowConfig>& rows = plan.rows(span.experiment);
  ChunkResult result;
  for (int unit = span.first_unit; unit < span.end_unit; ++unit) {
    ThrowIfStopped(stop);
    const int row = unit / config.realizations;
    for (schema::Attempt& attempt : engine::RunRealization(rows[static_cast<std::size_t>(row)], row, config.seed,
                                                           unit % config.realizations, components, samples)) {
      result.attempts.push_back(std::move(attempt));
    }
  }
  // One line an attempt (row names hold no line break: the config refuses them).
  for (const schema::Attempt& attempt : result.attempts) result.lines.append(report::AttemptLine(attempt, rows)).push_back('\n');
  return result;
}

std::uintmax_t ChunkBytes(const Plan& plan, const Shard& shard) {
  constexpr std::uintmax_t kBytesPerLine = 400, kBytesPerFile = 400;
  std::uintmax_t bytes = 0;
  for (int chunk = 0; chunk < static_cast<int>(plan.chunks().size()); ++chunk) {
    if (shard.Holds(chunk)) bytes += kBytesPerFile + kBytesPerLine * static_cast<std::uintmax_t>(plan.chunks()[static_cast<std::size_t>(chunk)].attempts);
  }
  return bytes;
}

std::string ChunkFileName(int chunk) {
  char name[32];
  std::snprintf(name, sizeof(name), "chunk-%06d.csv", chunk);
  return name;
}

// The first line of a chunk's text: which chunk of which plan, and a checksum of the lines below.
std::string IdentityLine(const Plan& plan, int chunk, std::string_view body) {
  return std::string(kChunkMark) + std::to_string(chunk) + " of plan " + plan.identity() + ", fnv1a64 " +
         io::Fingerprint(body);
}

std::string ChunkText(const Plan& plan, int chunk, const ChunkResult& result) {
  std::string body = std::string(report::kAttemptsColumns) + ",compute_s\n";
  body.reserve(body.size() + result.lines.size() + 16 * result.attempts.size());
  std::size_t at = 0;
  for (const schema::Attempt& attempt : result.attempts) {
    const std::size_t end = result.lines.find('\n', at);
    body.append(result.lines, at, end - at).append(",").append(io::FormatNumber(attempt.compute_s)).push_back('\n');
    at = end + 1;
  }
  return IdentityLine(plan, chunk, body) + '\n' + body;
}

namespace {

// The text below a chunk's identity line, once the line says it is `chunk` of `plan` and the
// checksum matches: anything else (an edit, lines swapped, another run's chunk) is refused.
std::string_view CheckedBody(const Plan& plan, int chunk, std::string_view text, const std::string& source) {
  const std::size_t newline = text.find('\n');
  const std::string_view first = text.substr(0, newline);
  if (newline == std::string_view::npos || first.rfind(kChunkMark, 0) != 0) {
    throw schema::InputError(source + ":1: not a chunk file (its first line is not '" + std::string(kChunkMark) + "...')");
  }
  const std::string_view body = text.substr(newline + 1);
  if (first != IdentityLine(plan, chunk, body)) {
    const std::string expected = IdentityLine(plan, chunk, body);
    const std::size_t checksum = expected.rfind(", fnv1a64 ");
    const bool same_chunk = first.substr(0, checksum) == std::string_view(expected).substr(0, checksum);
    throw schema::InputError(source + ":1: " +
                         (same_chunk ? "its lines do not match its checksum (edited or torn)"
                                     : "is not chunk " + std::to_string(chunk) + " of plan " + plan.identity() +
                                           " (another run's, or another chunk's): '" + io::Printable(first) + "'"));
  }
  return body;
}

}  // namespace

namespace {

// Every attempt of exactly the chunk's units, in order (one per anchor and trigger of its row);
// `line_of(i)` names attempt i's place in `source`.
void CheckUnits(const Plan& plan, int chunk, const std::vector<schema::Attempt>& attempts, const std::string& source,
                const std::function<std::string(std::size_t)>& place_of) {
  const ChunkSpan& span = plan.chunks()[static_cast<std::size_t>(chunk)];
  const int realizations = plan.experiments()[static_cast<std::size_t>(span.experiment)].realizations;
  const std::vector<schema::RowConfig>& rows = plan.rows(span.experiment);
  std::size_t next = 0;
  for (int unit = span.first_unit; unit < span.end_unit; ++unit) {
    const std::size_t expected = AttemptsPerUnit(rows[static_cast<std::size_t>(unit / realizations)]);
    for (std::size_t k = 0; k < expected; ++k, ++next) {
      if (next >= attempts.size()) {
        throw schema::InputError(source + ": ends within unit " + std::to_string(unit) + " (a chunk cut short?)");
      }
      const schema::Attempt& a = attempts[next];
      if (a.row < 0 || a.row >= static_cast<int>(rows.size()) || a.row * realizations + a.realization != unit) {
        const std::string row = a.row >= 0 && a.row < static_cast<int>(rows.size())
                                    ? rows[static_cast<std::size_t>(a.row)].name
                                    : std::to_string(a.row);
        throw schema::InputError(place_of(next) + ": an attempt of row " + row + ", realization " +
                                 std::to_string(a.realization) + " where unit " + std::to_string(unit) +
                                 "'s attempts belong");
      }
    }
  }
  if (next != attempts.size()) throw schema::InputError(place_of(next) + ": attempts beyond the chunk's units");
}

// The summaries' fields of an attempt, fixed size (what ParseAttempts reads from a line).
struct Record {
  std::int32_t row, realization, anchor_id, method;  // method: index into the row's triggers
  std::uint8_t initialized, has_error, has_nees, has_oracle, has_latency, padding[3];
  double t_init_s, error_m, nees_position, compute_s, t_oracle_s, latency_ratio;
};

}  // namespace

ChunkResult ParseChunk(const Plan& plan, int chunk, const std::string& text, const std::string& source) {
  const std::string_view body = CheckedBody(plan, chunk, text, source);
  const ChunkSpan& span = plan.chunks()[static_cast<std::size_t>(chunk)];
  report::AttemptsFile file = report::ParseAttempts(std::string(body), source, plan.rows(span.experiment));
  CheckUnits(plan, chunk, file.attempts, source, [&](std::size_t i) { return source + ":" + std::to_string(i + 2); });
  return {std::move(file.attempts), std::move(file.lines)};
}

std::string ChunkRecords(const Plan& plan, int chunk, const ChunkResult& result) {
  const std::vector<schema::RowConfig>& rows = plan.rows(plan.chunks()[static_cast<std::size_t>(chunk)].experiment);
  std::string records(result.attempts.size() * sizeof(Record), '\0');
  for (std::size_t i = 0; i < result.attempts.size(); ++i) {
    const schema::Attempt& a = result.attempts[i];
    const std::vector<std::string>& triggers = rows[static_cast<std::size_t>(a.row)].estimator.triggers;
    Record r{};
    r.row = a.row;
    r.realization = a.realization;
    r.anchor_id = a.anchor_id;
    r.method = static_cast<std::int32_t>(std::find(triggers.begin(), triggers.end(), a.method) - triggers.begin());
    r.initialized = a.initialized;
    r.t_init_s = a.t_init_s.value_or(0.0);
    if (a.evaluation) {
      r.has_error = a.evaluation->error_m.has_value();
      r.error_m = a.evaluation->error_m.value_or(0.0);
      r.has_nees = a.evaluation->nees_position.has_value();
      r.nees_position = a.evaluation->nees_position.value_or(0.0);
      r.has_oracle = a.evaluation->t_oracle_s.has_value();
      r.t_oracle_s = a.evaluation->t_oracle_s.value_or(0.0);
      r.has_latency = a.evaluation->latency_ratio.has_value();
      r.latency_ratio = a.evaluation->latency_ratio.value_or(0.0);
    }
    r.compute_s = a.compute_s;
    std::memcpy(records.data() + i * sizeof(Record), &r, sizeof(Record));
  }
  return records;
}

ChunkResult FromRecords(const Plan& plan, int chunk, std::string_view text, std::string_view records,
                        const std::string& source) {
  if (records.size() % sizeof(Record) != 0) throw schema::InputError(source + ": records cut short");
  const std::vector<schema::RowConfig>& rows = plan.rows(plan.chunks()[static_cast<std::size_t>(chunk)].experiment);
  ChunkResult result;
  result.attempts.resize(records.size() / sizeof(Record));
  for (std::size_t i = 0; i < result.attempts.size(); ++i) {
    Record r;
    std::memcpy(&r, records.data() + i * sizeof(Record), sizeof(Record));
    schema::Attempt& a = result.attempts[i];
    a.row = r.row;
    a.realization = r.realization;
    a.anchor_id = r.anchor_id;
    if (r.row < 0 || r.row >= static_cast<int>(rows.size()) || r.method < 0 ||
        r.method >= static_cast<int>(rows[static_cast<std::size_t>(r.row)].estimator.triggers.size())) {
      throw schema::InputError(source + ": record " + std::to_string(i) + " names no row and trigger of the plan");
    }
    a.method = rows[static_cast<std::size_t>(r.row)].estimator.triggers[static_cast<std::size_t>(r.method)];
    a.initialized = r.initialized != 0;
    if (a.initialized || r.has_oracle) a.evaluation.emplace();
    if (a.initialized) {  // as ParseAttempts reads a line
      a.t_init_s = r.t_init_s;
      if (r.has_error) a.evaluation->error_m = r.error_m;
      if (r.has_nees) a.evaluation->nees_position = r.nees_position;
      if (r.has_latency) a.evaluation->latency_ratio = r.latency_ratio;
    }
    if (r.has_oracle) a.evaluation->t_oracle_s = r.t_oracle_s;
    a.compute_s = r.compute_s;
  }
  CheckUnits(plan, chunk, result.attempts, source, [&](std::size_t i) { return source + ": record " + std::to_string(i); });
  // The lines: below the identity and header lines, each without its last field (compute_s),
  // copied into one text.
  result.lines.reserve(text.size());
  std::size_t count = 0;
  std::size_t at = text.find('\n');
  at = at == std::string_view::npos ? text.size() : text.find('\n', at + 1);
  while (at != std::string_view::npos && at + 1 < text.size()) {
    const std::size_t end = std::min(text.find('\n', at + 1), text.size());
    const std::string_view line = text.substr(at + 1, end - at - 1);
    result.lines.append(line.substr(0, line.rfind(','))).push_back('\n');
    ++count;
    at = end < text.size() ? end : std::string_view::npos;
  }
  if (count != result.attempts.size()) {
    throw schema::InputError(source + ": " + std::to_string(count) + " lines for " +
                             std::to_string(result.attempts.size()) + " records");
  }
  return result;
}

ChunkResult ReadChunkFile(const Plan& plan, int chunk, const std::string& path) {
  return ParseChunk(plan, chunk, io::ReadWholeFile(path), path);
}

}  // namespace anchorbench::engine
