#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "anchorbench/experiments/atomic_file.hpp"
#include "anchorbench/experiments/commands.hpp"
#include "anchorbench/experiments/config.hpp"
#include "anchorbench/experiments/csv_reader.hpp"
#include "anchorbench/experiments/input_error.hpp"
#include "anchorbench/experiments/monte_carlo.hpp"
#include "anchorbench/experiments/output_folder.hpp"
#include "anchorbench/experiments/progress.hpp"
#include "anchorbench/experiments/run_outputs.hpp"
#include "anchorbench/experiments/summary.hpp"
#include "anchorbench/experiments/sweep.hpp"

namespace anchorbench::experiments {
namespace {

// The axes: the config's `sweep` section, then the command line's (which replace an axis of the
// same key).
std::vector<SweepAxis> Axes(const ExperimentConfig& config, const std::vector<std::string>& assignments) {
  std::vector<SweepAxis> axes;
  for (const auto& [key, values] : config.sweep) axes.push_back(ParseSweepAxis(key, values));
  for (const std::string& assignment : assignments) {
    SweepAxis axis = ParseSweepAssignment(assignment);
    auto same = std::find_if(axes.begin(), axes.end(), [&](const SweepAxis& a) { return a.key == axis.key; });
    if (same != axes.end()) {
      *same = std::move(axis);
    } else {
      axes.push_back(std::move(axis));
    }
  }
  return axes;
}

std::string Cell(const std::optional<double>& value, int decimals) {
  return value ? FormatFixed(*value, decimals) : "-";
}

struct PointResult {
  std::vector<std::string> values;  // one per axis
  std::vector<RowConfig> rows;
  std::vector<MethodSummary> summaries;
};

}  // namespace

int SweepCommand(const SweepArgs& args) {
  const ExperimentConfig base = LoadConfig(args.config);
  const std::vector<SweepAxis> axes = Axes(base, args.axes);
  if (axes.empty()) {
    throw InputError(args.config + ": nothing to sweep: give --set KEY=VALUES or a 'sweep' section");
  }
  // Every grid point is parsed and validated before the first trial runs.
  std::vector<ExperimentConfig> configs;
  int total_tasks = 0;
  for (const std::vector<std::string>& point : SweepGrid(axes)) {
    ExperimentConfig config = LoadConfig(args.config, point);
    if (args.realizations) config.realizations = *args.realizations;
    total_tasks += static_cast<int>(RowsOf(config).size()) * config.realizations;
    configs.push_back(std::move(config));
  }
  const int threads = ResolveThreads(args.threads);
  const std::filesystem::path out = OutputFolder(args.out, base.name);

  Progress progress("sweep " + base.name, args.quiet);
  std::vector<PointResult> results;
  int tasks_done = 0;
  for (std::size_t p = 0; p < configs.size(); ++p) {
    const ExperimentConfig& config = configs[p];
    const std::vector<Attempt> attempts = RunMonteCarlo(
        config, {threads, [&](int done, int) { progress.Update(tasks_done + done, total_tasks); }});
    PointResult result;
    for (std::size_t a = 0; a < axes.size(); ++a) result.values.push_back(axes[a].values[0]);
    std::size_t stride = configs.size();
    std::size_t index = p;
    for (std::size_t a = 0; a < axes.size(); ++a) {  // the grid's first axis varies slowest
      stride /= axes[a].values.size();
      result.values[a] = axes[a].values[index / stride];
      index %= stride;
    }
    result.rows = RowsOf(config);
    result.summaries = Summarize(attempts, result.rows, config.realizations, config.bootstrap_resamples, config.seed);
    tasks_done += static_cast<int>(result.rows.size()) * config.realizations;
    results.push_back(std::move(result));
  }
  const double wall_time_s = progress.elapsed_s();
  progress.Finish(total_tasks);

  AtomicFile csv(out / "sweep.csv");
  for (const SweepAxis& axis : axes) csv.stream() << axis.key << ',';
  csv.stream() << kSummaryColumns << '\n';
  AtomicFile timing(out / "timing.csv");
  for (const SweepAxis& axis : axes) timing.stream() << axis.key << ',';
  timing.stream() << kTimingColumns << '\n';
  std::ostringstream md;
  md << "# " << base.name << ": sweep\n\n" << configs.front().realizations << " realizations per point and row, seed "
     << configs.front().seed << ".\n\n|";
  for (const SweepAxis& axis : axes) md << ' ' << axis.key << " |";
  md << " Row | Method | Avg. (m) | Med. (m) | Init. | >1m | Ratio (%) |\n|";
  for (std::size_t a = 0; a < axes.size() + 7; ++a) md << "---|";
  md << '\n';
  for (const PointResult& result : results) {
    for (const MethodSummary& s : result.summaries) {
      for (const std::string& value : result.values) csv.stream() << value << ',';
      csv.stream() << SummaryCsvFields(s, result.rows) << '\n';
      for (const std::string& value : result.values) timing.stream() << value << ',';
      timing.stream() << TimingCsvFields(s, result.rows) << '\n';
      md << '|';
      for (const std::string& value : result.values) md << ' ' << value << " |";
      md << ' ' << result.rows[static_cast<std::size_t>(s.row)].name << " | " << s.method << " | "
         << Cell(s.avg_m, 3) << " | " << Cell(s.med_m, 3) << " | " << s.init << " | " << s.gt1m << " | "
         << Cell(s.ratio_pct, 2) << " |\n";
    }
  }
  AtomicFile markdown(out / "sweep.md");
  markdown.stream() << md.str();
  std::vector<std::string> axis_text;
  for (const SweepAxis& axis : axes) {
    std::string values;
    for (const std::string& v : axis.values) values += (values.empty() ? "" : ",") + v;
    axis_text.push_back(axis.key + "=" + values);
  }
  AtomicFile manifest(out / "manifest.json");
  manifest.stream() << ManifestJson(base, {args.config, threads, wall_time_s, axis_text});
  csv.Commit();
  timing.Commit();
  markdown.Commit();
  manifest.Commit();
  if (!args.quiet) std::cout << md.str();
  return 0;
}

}  // namespace anchorbench::experiments
