#include "anchorbench/engine/commit.hpp"

#include <sstream>

#include "anchorbench/engine/chunk.hpp"
#include "anchorbench/report/summary.hpp"
#include "anchorbench/report/sweep_report.hpp"

namespace anchorbench::engine {
namespace {

constexpr std::uintmax_t kTables = 1 << 16;

}  // namespace

std::string CommitRun(io::ResultFolder& out, const schema::ExperimentConfig& config, const ExperimentAttempts& run,
                      const report::RunInfo& info) {
  const std::vector<schema::RowConfig> rows = schema::RowsOf(config);
  // Every file into the new folder, then the folder in place: an error leaves the old results intact.
  out.Write("attempts.csv", [&](std::ostream& file) { report::WriteAttemptLines(file, run.lines); });
  const std::vector<report::MethodSummary> summaries =
      report::Summarize(run.attempts, rows, config.realizations, config.bootstrap_resamples, config.seed);
  out.Write("summary.csv", [&](std::ostream& file) { report::WriteSummaryCsv(file, summaries, rows); });
  std::ostringstream markdown;
  report::WriteSummaryMarkdown(markdown, summaries, rows, config);
  out.Write("summary.md", markdown.str());
  out.Write("timing.csv", [&](std::ostream& file) { report::WriteTimingCsv(file, summaries, rows); });
  out.Write("manifest.json", report::ManifestJson(config, info));
  out.Commit();
  return markdown.str();
}

std::string CommitSweep(io::ResultFolder& out, const std::string& name, const std::vector<schema::SweepAxis>& axes,
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
  out.Write("sweep.csv", [&](std::ostream& file) { report::WriteSweepCsv(file, axes, results); });
  out.Write("timing.csv", [&](std::ostream& file) { report::WriteSweepTiming(file, axes, results); });
  std::ostringstream markdown;
  report::WriteSweepMarkdown(markdown, name, first.realizations, first.seed, axes, results);
  out.Write("sweep.md", markdown.str());
  info.sweep_axes = schema::DescribeAxes(axes);
  out.Write("manifest.json", report::ManifestJson(first, info));
  out.Commit();
  return markdown.str();
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
