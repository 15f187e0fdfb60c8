#include <filesystem>
#include <iostream>
#include <memory>

#include "anchorbench/experiments/atomic_file.hpp"
#include "anchorbench/experiments/commands.hpp"
#include "anchorbench/experiments/config.hpp"
#include "anchorbench/experiments/input_error.hpp"
#include "anchorbench/experiments/output_folder.hpp"
#include "anchorbench/experiments/replay.hpp"

namespace anchorbench::experiments {

int ReplayCommand(const ReplayArgs& args) {
  ExperimentConfig config;
  if (!args.config.empty()) config = LoadConfig(args.config);
  const PoseTracks poses = PoseTracks::Load(args.poses);
  const std::vector<RangeRecord> ranges = LoadRanges(args.ranges);
  std::map<int, AnchorTruth> truth;
  if (!args.anchors.empty()) truth = LoadAnchors(args.anchors);
  CheckReplayable(ranges, args.anchors.empty() ? nullptr : &truth, config.estimator);
  if (!args.out.empty()) CreateFolder(args.out);

  std::unique_ptr<AtomicFile> trace_file;
  TraceSink trace;
  if (!args.trace.empty()) {
    trace_file = std::make_unique<AtomicFile>(args.trace);
    trace_file->stream() << kTraceHeader << '\n';
    trace = [&](const RangeRecord& r, const estimator::FeedResult& fed) { WriteTraceRow(trace_file->stream(), r, fed); };
  }
  const ReplayResult result = Replay(poses, ranges, args.anchors.empty() ? nullptr : &truth, config.estimator, trace, config.seed);
  if (result.ranges_skipped > 0) {
    std::cerr << args.ranges << ": " << result.ranges_skipped
              << " ranges outside their tag's pose time span were skipped, never extrapolated (first at line "
              << result.first_skipped_line << ")\n";
  }
  PrintEstimates(std::cout, result.outcomes);
  if (trace_file) trace_file->Commit();
  if (!args.out.empty()) {
    AtomicFile estimates(std::filesystem::path(args.out) / "estimates.csv");
    WriteEstimates(estimates.stream(), result.outcomes);
    estimates.Commit();
  }
  return 0;
}

}  // namespace anchorbench::experiments
