#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "anchorbench/experiments/atomic_file.hpp"
#include "anchorbench/experiments/commands.hpp"
#include "anchorbench/experiments/config.hpp"
#include "anchorbench/experiments/input_error.hpp"
#include "anchorbench/experiments/monte_carlo.hpp"
#include "anchorbench/experiments/output_folder.hpp"
#include "anchorbench/experiments/progress.hpp"
#include "anchorbench/experiments/run_outputs.hpp"
#include "anchorbench/experiments/summary.hpp"

namespace anchorbench::experiments {

int RunCommand(const RunArgs& args) {
  ExperimentConfig config = LoadConfig(args.config, args.overrides);
  if (args.seed) config.seed = *args.seed;
  if (args.realizations) config.realizations = *args.realizations;
  const int threads = ResolveThreads(args.threads);
  const std::filesystem::path out = OutputFolder(args.out, config.name);

  Progress progress("run " + config.name, args.quiet);
  const std::vector<RowConfig> rows = RowsOf(config);
  const std::vector<Attempt> attempts =
      RunMonteCarlo(config, {threads, [&](int done, int total) { progress.Update(done, total); }});
  const double wall_time_s = progress.elapsed_s();
  progress.Finish(static_cast<int>(rows.size()) * config.realizations);
  const std::vector<MethodSummary> summaries = Summarize(attempts, rows, config.realizations,
                                                         config.bootstrap_resamples, config.seed);

  // Build every file first, then commit them together: an error leaves the old results intact.
  AtomicFile attempts_file(out / "attempts.csv");
  WriteAttempts(attempts_file.stream(), attempts, rows);
  AtomicFile summary_csv(out / "summary.csv");
  WriteSummaryCsv(summary_csv.stream(), summaries, rows);
  std::ostringstream markdown;
  WriteSummaryMarkdown(markdown, summaries, rows, config);
  AtomicFile summary_md(out / "summary.md");
  summary_md.stream() << markdown.str();
  AtomicFile timing(out / "timing.csv");
  timing.stream() << kTimingColumns << '\n';
  for (const MethodSummary& s : summaries) timing.stream() << TimingCsvFields(s, rows) << '\n';
  AtomicFile manifest(out / "manifest.json");
  manifest.stream() << ManifestJson(config, {args.config, threads, wall_time_s, {}});
  attempts_file.Commit();
  summary_csv.Commit();
  summary_md.Commit();
  timing.Commit();
  manifest.Commit();
  if (!args.quiet) std::cout << markdown.str();
  return 0;
}

}  // namespace anchorbench::experiments
