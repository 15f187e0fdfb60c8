#include "anchorbench/engine/chunk.hpp"

#include <cstdio>

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
                         std::vector<estimator::RangeSample>& samples) {
  const ChunkSpan& span = plan.chunks()[static_cast<std::size_t>(chunk)];
  const schema::ExperimentConfig& config = plan.experiments()[static_cast<std::size_t>(span.experiment)];
  const std::vector<schema::RowConfig>& rows = plan.rows(span.experiment);
  ChunkResult result;
  for (int unit = span.first_unit; unit < span.end_unit; ++unit) {
    const int row = unit / config.realizations;
    for (schema::Attempt& attempt : engine::RunRealization(rows[static_cast<std::size_t>(row)], row, config.seed,
                                                           unit % config.realizations, components, samples)) {
      result.attempts.push_back(std::move(attempt));
    }
  }
  // One line an attempt (row names hold no line break: the config refuses them).
  result.lines.reserve(result.attempts.size());
  for (const schema::Attempt& attempt : result.attempts) result.lines.push_back(report::AttemptLine(attempt, rows));
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
  for (std::size_t i = 0; i < result.lines.size(); ++i) {
    body += result.lines[i] + ',' + io::FormatNumber(result.attempts[i].compute_s) + '\n';
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

ChunkResult ParseChunk(const Plan& plan, int chunk, const std::string& text, const std::string& source) {
  const std::string_view body = CheckedBody(plan, chunk, text, source);
  const ChunkSpan& span = plan.chunks()[static_cast<std::size_t>(chunk)];
  const int realizations = plan.experiments()[static_cast<std::size_t>(span.experiment)].realizations;
  const std::vector<schema::RowConfig>& rows = plan.rows(span.experiment);
  report::AttemptsFile file = report::ParseAttempts(std::string(body), source, rows);
  // Unit by unit: each of the chunk's units in order, whole.
  std::size_t next = 0;
  for (int unit = span.first_unit; unit < span.end_unit; ++unit) {
    const std::size_t expected = AttemptsPerUnit(rows[static_cast<std::size_t>(unit / realizations)]);
    for (std::size_t k = 0; k < expected; ++k, ++next) {
      if (next >= file.attempts.size()) {
        throw schema::InputError(source + ": ends within unit " + std::to_string(unit) + " (a chunk cut short?)");
      }
      const schema::Attempt& a = file.attempts[next];
      if (a.row * realizations + a.realization != unit) {
        throw schema::InputError(source + ":" + std::to_string(next + 2) + ": an attempt of row " +
                             rows[static_cast<std::size_t>(a.row)].name + ", realization " +
                             std::to_string(a.realization) + " where unit " + std::to_string(unit) +
                             "'s attempts belong");
      }
    }
  }
  if (next != file.attempts.size()) {
    throw schema::InputError(source + ":" + std::to_string(next + 2) + ": attempts beyond the chunk's units");
  }
  return {std::move(file.attempts), std::move(file.lines)};
}

ChunkResult ReadChunkFile(const Plan& plan, int chunk, const std::string& path) {
  return ParseChunk(plan, chunk, io::ReadWholeFile(path), path);
}

}  // namespace anchorbench::engine
