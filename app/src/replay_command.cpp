#include <filesystem>
#include <iostream>
#include <memory>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/atomic_file.hpp"
#include "anchorbench/io/recorded_data.hpp"
#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/report/replay_report.hpp"
#include "anchorbench/runner/replay.hpp"
#include "commands.hpp"

namespace anchorbench::app {
namespace {

std::vector<std::filesystem::path> Inputs(const ReplayArgs& args) {
  std::vector<std::filesystem::path> inputs = {args.poses, args.ranges};
  for (const std::string& optional : {args.anchors, args.config}) {
    if (!optional.empty()) inputs.emplace_back(optional);
  }
  return inputs;
}

}  // namespace

int ReplayCommand(const ReplayArgs& args, const AppContext& app) {
  runner::ExperimentConfig config;  // the defaults, unless --config names a file
  if (!args.config.empty()) config = config::LoadConfig(args.config, {}, app.parts);
  const std::vector<io::PoseRecord> poses = io::LoadPoses(args.poses);
  const std::vector<io::RangeRecord> ranges = io::LoadRanges(args.ranges);
  std::map<int, eval::AnchorTruth> truth;
  if (!args.anchors.empty()) truth = io::LoadAnchors(args.anchors);
  const std::map<int, eval::AnchorTruth>* known = args.anchors.empty() ? nullptr : &truth;
  runner::CheckReplayable(ranges, known, config.estimator, app.parts);

  // The outputs, before any work: never an input, never earlier results without --overwrite.
  std::unique_ptr<io::ResultFolder> out;
  if (!args.out.empty()) {
    io::ResultFolder::Options options;
    options.overwrite = args.overwrite;
    options.expected_bytes = 1 << 16;
    options.inputs = Inputs(args);
    out = std::make_unique<io::ResultFolder>(args.out, options);
  }
  std::unique_ptr<io::AtomicFile> trace_file;
  runner::TraceSink trace;
  if (!args.trace.empty()) {
    trace_file = std::make_unique<io::AtomicFile>(args.trace, args.overwrite, Inputs(args));
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
  if (out) {
    out->Write("estimates.csv", [&](std::ostream& file) { report::WriteEstimates(file, result.attempts); });
    out->Commit();
  }
  return 0;
}

}  // namespace anchorbench::app
