#include <filesystem>
#include <iostream>
#include <memory>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/atomic_file.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/io/log_reader.hpp"
#include "anchorbench/io/recorded_data.hpp"
#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/report/replay_report.hpp"
#include "anchorbench/report/replay_summary.hpp"
#include "anchorbench/engine/replay.hpp"
#include "commands.hpp"
#include "progress.hpp"

namespace anchorbench::app {
namespace {

constexpr double kBytesPerMb = 1e6;  // progress counts bytes read, shows megabytes

std::vector<std::filesystem::path> Inputs(const ReplayArgs& args) {
  std::vector<std::filesystem::path> inputs = {args.poses};
  for (const std::string& ranges : args.ranges) inputs.emplace_back(ranges);
  for (const std::string& optional : {args.anchors, args.config}) {
    if (!optional.empty()) inputs.emplace_back(optional);
  }
  return inputs;
}

io::LogPolicy PolicyOf(const ReplayArgs& args) {
  io::LogPolicy policy = args.policy;
  policy.repeated_poses = io::RepeatedPosesFromName(args.repeated_poses);
  policy.out_of_order = io::OutOfOrderFromName(args.out_of_order);
  return policy;
}

// The first pass: every file read to the end under the policy, so that a malformed file or a
// refused row ends the command before any output exists.
io::LogSurvey Survey(const io::LogFiles& files, const io::LogPolicy& policy, bool quiet) {
  Progress progress("replay: checking", quiet, "MB", kBytesPerMb);
  io::LogSurvey survey =
      io::SurveyLog(files, policy, [&](std::uint64_t done, std::uint64_t total) { progress.Update(done, total); });
  if (!quiet && progress.elapsed_s() > 1.0) progress.Finish(static_cast<long long>(survey.bytes));
  return survey;
}

}  // namespace

int ReplayCommand(const ReplayArgs& args, const AppContext& app) {
  schema::ExperimentConfig config;  // the defaults, unless --config names a file
  if (!args.config.empty()) config = config::LoadConfig(args.config, {}, app.components);
  const io::LogPolicy policy = PolicyOf(args);
  const io::LogFiles files{args.poses, args.ranges};
  const io::LogSurvey survey = Survey(files, policy, args.quiet);
  std::map<int, schema::AnchorTruth> truth;
  if (!args.anchors.empty()) truth = io::LoadAnchors(args.anchors);
  const std::map<int, schema::AnchorTruth>* known = args.anchors.empty() ? nullptr : &truth;
  engine::CheckReplayable(survey.anchor_ids, known, config.estimator, app.components);

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
  engine::TraceSink trace;
  if (!args.trace.empty()) {
    if (out && io::IsInside(args.trace, out->target())) {
      throw schema::InputError("--trace " + args.trace + ": lies inside --out " + args.out +
                           ", which is replaced as a whole; put the trace beside it");
    }
    constexpr std::uintmax_t kBytesPerTraceRow = 64;
    trace_file = std::make_unique<io::AtomicFile>(args.trace, args.overwrite, Inputs(args),
                                                  kBytesPerTraceRow * static_cast<std::uintmax_t>(survey.range_rows));
    trace_file->stream() << report::kTraceHeader << '\n';
    trace = [&](const io::RangeRecord& r, const estimator::FeedResult& fed) {
      report::WriteTraceRow(trace_file->stream(), r, fed);
    };
  }

  // The second pass, streamed: one row at a time from the files into the front end.
  report::ReplaySummary summary{files, policy, survey.pose_rows, survey.range_rows, {}, {}, survey.reordered_rows};
  io::RecordedLog log(files, policy, survey.default_tag_id, summary.drops);
  Progress progress("replay", args.quiet, "MB", kBytesPerMb);
  std::int64_t rows = 0;
  const engine::LogSource source = [&](io::RecordedLog::Kind& kind, io::PoseRecord& pose, io::RangeRecord& range) {
    if ((++rows & 0xffff) == 0) progress.Update(static_cast<long long>(log.bytes_read()), static_cast<long long>(survey.bytes));
    return log.Next(kind, pose, range);
  };
  const engine::ReplayResult result =
      engine::Replay(source, files.ranges, known, config.estimator, app.components, config.seed, trace);
  if (progress.elapsed_s() > 1.0) progress.Finish(static_cast<long long>(survey.bytes));
  summary.drops.Add(result.drops);
  summary.samples_by_anchor = result.samples_by_anchor;

  if (!args.quiet) report::PrintReplaySummary(std::cerr, summary);
  report::PrintEstimates(std::cout, result.attempts);
  if (trace_file) trace_file->Commit();
  if (out) {
    out->Write("estimates.csv", [&](std::ostream& file) { report::WriteEstimates(file, result.attempts); });
    out->Write("replay_summary.json", [&](std::ostream& file) { report::WriteReplaySummaryJson(file, summary); });
    out->Write("replay_summary.md", [&](std::ostream& file) { report::WriteReplaySummaryMarkdown(file, summary); });
    out->Commit();
  }
  return 0;
}

}  // namespace anchorbench::app
