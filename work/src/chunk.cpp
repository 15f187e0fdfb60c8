#include "anchorbench/work/chunk.hpp"

#include <cstdio>
#include <sstream>

#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/io/input_error.hpp"
#include "anchorbench/report/run_outputs.hpp"
#include "anchorbench/report/attempts_file.hpp"
#include "anchorbench/runner/monte_carlo.hpp"

namespace anchorbench::work {
namespace {

// The attempts a run writes for one unit: one per anchor and trigger.
std::size_t AttemptsPerUnit(const runner::RowConfig& row) {
  return static_cast<std::size_t>(row.scenario.NumAnchors()) * row.estimator.triggers.size();
}

}  // namespace

ChunkResult ComputeChunk(const Plan& plan, int chunk, const registry::Components& components,
                         std::vector<estimator::RangeSample>& samples) {
  const ChunkSpan& span = plan.chunks()[static_cast<std::size_t>(chunk)];
  const runner::ExperimentConfig& config = plan.experiments()[static_cast<std::size_t>(span.experiment)];
  const std::vector<runner::RowConfig>& rows = plan.rows(span.experiment);
  ChunkResult result;
  for (int unit = span.first_unit; unit < span.end_unit; ++unit) {
    const int row = unit / config.realizations;
    for (runner::Attempt& attempt : runner::RunRealization(rows[static_cast<std::size_t>(row)], row, config.seed,
                                                           unit % config.realizations, components, samples)) {
      result.attempts.push_back(std::move(attempt));
    }
  }
  std::ostringstream csv;
  report::WriteAttempts(csv, result.attempts, rows);
  std::istringstream lines(csv.str());
  std::string line;
  std::getline(lines, line);  // the header
  while (std::getline(lines, line)) result.lines.push_back(line);
  return result;
}

std::string ChunkFileName(int chunk) {
  char name[32];
  std::snprintf(name, sizeof(name), "chunk-%06d.csv", chunk);
  return name;
}

std::string ChunkText(const ChunkResult& result) {
  std::string text = std::string(report::kAttemptsColumns) + ",compute_s\n";
  for (std::size_t i = 0; i < result.lines.size(); ++i) {
    text += result.lines[i] + ',' + io::FormatNumber(result.attempts[i].compute_s) + '\n';
  }
  return text;
}

ChunkResult ParseChunk(const Plan& plan, int chunk, const std::string& text, const std::string& source) {
  const ChunkSpan& span = plan.chunks()[static_cast<std::size_t>(chunk)];
  const int realizations = plan.experiments()[static_cast<std::size_t>(span.experiment)].realizations;
  const std::vector<runner::RowConfig>& rows = plan.rows(span.experiment);
  report::AttemptsFile file = report::ParseAttempts(text, source, rows);
  // Unit by unit: each of the chunk's units in order, whole.
  std::size_t next = 0;
  for (int unit = span.first_unit; unit < span.end_unit; ++unit) {
    const std::size_t expected = AttemptsPerUnit(rows[static_cast<std::size_t>(unit / realizations)]);
    for (std::size_t k = 0; k < expected; ++k, ++next) {
      if (next >= file.attempts.size()) {
        throw io::InputError(source + ": ends within unit " + std::to_string(unit) + " (a chunk cut short?)");
      }
      const runner::Attempt& a = file.attempts[next];
      if (a.row * realizations + a.realization != unit) {
        throw io::InputError(source + ":" + std::to_string(next + 2) + ": an attempt of row " +
                             rows[static_cast<std::size_t>(a.row)].name + ", realization " +
                             std::to_string(a.realization) + " where unit " + std::to_string(unit) +
                             "'s attempts belong");
      }
    }
  }
  if (next != file.attempts.size()) {
    throw io::InputError(source + ":" + std::to_string(next + 2) + ": attempts beyond the chunk's units");
  }
  return {std::move(file.attempts), std::move(file.lines)};
}

ChunkResult ReadChunkFile(const Plan& plan, int chunk, const std::string& path) {
  return ParseChunk(plan, chunk, io::ReadWholeFile(path), path);
}

}  // namespace anchorbench::work
