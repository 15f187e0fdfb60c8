#include <filesystem>
#include <iostream>
#include <memory>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/atomic_file.hpp"
#include "anchorbench/io/output_folder.hpp"
#include "anchorbench/io/recorded_data.hpp"
#include "anchorbench/report/replay_report.hpp"
#include "anchorbench/runner/replay.hpp"
#include "commands.hpp"

namespace anchorbench::app {

int ReplayCommand(const ReplayArgs& args, const AppContext& app) {
  runner::ExperimentConfig config;  // the defaults, unless --config names a file
  if (!args.config.empty()) config = config::LoadConfig(args.config, {}, app.parts);
  const std::vector<io::PoseRecord> poses = io::LoadPoses(args.poses);
  const std::vector<io::RangeRecord> ranges = io::LoadRanges(args.ranges);
  std::map<int, eval::AnchorTruth> truth;
  if (!args.anchors.empty()) truth = io::LoadAnchors(args.anchors);
  const std::map<int, eval::AnchorTruth>* known = args.anchors.empty() ? nullptr : &truth;
  runner::CheckReplayable(ranges, known, config.estimator, app.parts);
  if (!args.out.empty()) io::CreateFolder(args.out);

  std::unique_ptr<io::AtomicFile> trace_file;
  runner::TraceSink trace;
  if (!args.trace.empty()) {
    trace_file = std::make_unique<io::AtomicFile>(args.trace);
    trace_file->stream() << report::kTraceHeader << '\n';
    trace = [&](const io::RangeRecord& r, const estimator::FeedResult& fed) {
      report::WriteTraceRow(trace_file->stream(), r, fed);
    };
  }
  const runner::ReplayResult result =
      runner::Replay(poses, ranges, known, config.estimator, app.parts, config.seed, trace);
  if (result.ranges_skipped > 0) {
    std::cerr << args.ranges << ": " << result.ranges_skipped
              << " ranges outside their tag's pose time span were skipped, never extrapolated (first at line "
              << result.first_skipped_line << ")\n";
  }
  report::PrintEstimates(std::cout, result.attempts);
  if (trace_file) trace_file->Commit();
  if (!args.out.empty()) {
    io::AtomicFile estimates(std::filesystem::path(args.out) / "estimates.csv");
    report::WriteEstimates(estimates.stream(), result.attempts);
    estimates.Commit();
  }
  return 0;
}

}  // namespace anchorbench::app
