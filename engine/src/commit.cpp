#include "anchorbench/engine/commit.hpp"

#include <sstream>

#include "anchorbench/engine/chunk.hpp"
#include "anchorbench/report/summary.hpp"
#include "anchorbench/report/sweep_report.hpp"

namespace anchorbench::engine {
namespace {

constexpr std::uintmax_t kTables = 1 << 16;

}  // namespace

std::string WriteRunFiles(const FileWriter& write, const schema::ExperimentConfig& config, const ExperimentAttempts& run,
                          const report::RunInfo& info) {
  const std::vector<schema::RowConfig> rows = schema::RowsOf(config);
  write("attempts.csv", [&](std::ostream& file) { report::WriteAttemptLines(file, run.lines); });
  const std::vector<report::MethodSummary> summaries =
      report::Summarize(run.attempts, rows, config.realizations, config.bootstrap_resamples, config.seed);
  write("summary.csv", [&](std::ostream& file) { report::WriteSummaryCsv(file, summaries, rows); });
  std::ostringstream markdown;
  report::WriteSummaryMarkdown(markdown, summaries, rows, config);
  write("summary.md", [&](std::ostream& file) { file << markdown.str(); });
  write("timing.csv", [&](std::ostream& file) { report::WriteTimingCsv(file, summaries, rows); });
  write("manifest.json", [&](std::ostream& file) { file << report::ManifestJson(config, info); });
  return markdown.str();
}

std::string WriteSweepFiles(const FileWriter& write, const std::string& name, const std::vector<schema::SweepAxis>& axes,
                            const Plan& plan, const std::vector<ExperimentAttempts>& points, report::RunInfo info) {
  const std::vector<schema::SweepPoint> grid = schema::SweepGrid(axes);
  std::vector<report::SweepPointResult> results;
  for (std::size_t p = 0; p < grid.size(); ++p) {
    const schema::ExperimentConfig& config = plan.experiments()[p];
    report::SweepPointResult result{grid[p], plan.rows(static_cast<int>(p)), {}};
    result.summaries =
        report::Summarize(points[p].attempts, result.rows, config.realizations, config.bootstrap_resamples, config.seed);
    results.push_back(std::move(result));
  }
  const schema::ExperimentConfig& first = plan.experiments().front();
  write("sweep.csv", [&](std::ostream& file) { report::WriteSweepCsv(file, axes, results); });
  write("timing.csv", [&](std::ostream& file) { report::WriteSweepTiming(file, axes, results); });
  std::ostringstream markdown;
  report::WriteSweepMarkdown(markdown, name, first.realizations, first.seed, axes, results);
  write("sweep.md", [&](std::ostream& file) { file << markdown.str(); });
  info.sweep_axes = schema::DescribeAxes(axes);
  write("manifest.json", [&](std::ostream& file) { file << report::ManifestJson(first, info); });
  return markdown.str();
}

namespace {

FileWriter Into(io::ResultFolder& out) {
  return [&out](const std::string& name, const std::function<void(std::ostream&)>& write) { out.Write(name, write); };
}

}  // namespace

std::string CommitRun(io::ResultFolder& out, const schema::ExperimentConfig& config, const ExperimentAttempts& run,
                      const report::RunInfo& info) {
  // Every file into the new folder, then the folder in place: an error leaves the old results intact.
  const std::string markdown = WriteRunFiles(Into(out), config, run, info);
  out.Commit();
  return markdown;
}

std::string CommitSweep(io::ResultFolder& out, const std::string& name, const std::vector<schema::SweepAxis>& axes,
                        const Plan& plan, const std::vector<ExperimentAttempts>& points, report::RunInfo info) {
  const std::string markdown = WriteSweepFiles(Into(out), name, axes, plan, points, std::move(info));
  out.Commit();
  return markdown;
}

std::uintmax_t RunResultBytes(const Plan& plan, const std::optional<Shard>& shard) {
  constexpr std::uintmax_t kBytesPerAttempt = 360;
  if (shard) return ChunkBytes(plan, *shard) + kTables;
  return kBytesPerAttempt * static_cast<std::uintmax_t>(plan.attempts()) + kTables;
}

std::uintmax_t SweepResultBytes(const Plan& plan, const std::optional<Shard>& shard) {
  if (shard) return RunResultBytes(plan, shard);
  std::uintmax_t lines = 0;
  for (const schema::ExperimentConfig& config : plan.experiments()) {
    for (const schema::RowConfig& row : schema::RowsOf(config)) lines += row.estimator.triggers.size();
  }
  return 600 * lines + kTables;
}

}  // namespace anchorbench::engine
