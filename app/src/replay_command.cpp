#include <filesystem>
#include <iostream>
#include <memory>

#include "anchorbench/config/config_yaml.hpp"
#include "anchorbench/config/load_config.hpp"
#include "anchorbench/io/atomic_file.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/io/recorded_data.hpp"
#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/report/replay_report.hpp"
#include "anchorbench/report/why_not.hpp"
#include "anchorbench/engine/monte_carlo.hpp"
#include "anchorbench/studies/navigation_log.hpp"
#include "anchorbench/studies/replay_log.hpp"
#include "commands.hpp"
#include "progress.hpp"

namespace anchorbench::app {
namespace {

constexpr double kBytesPerMb = 1e6;  // progress counts bytes read, shows megabytes

std::vector<std::filesystem::path> Inputs(const ReplayArgs& args) {
  std::vector<std::filesystem::path> inputs = {args.poses};
  for (const std::string& ranges : args.ranges) inputs.emplace_back(ranges);
  if (!args.anchors.empty()) inputs.emplace_back(args.anchors);
  if (!args.config.empty()) {
    for (const std::string& file : config::ConfigFiles(args.config)) inputs.emplace_back(file);  // and its bases
  }
  return inputs;
}

// A trace file beside --out (never inside the folder, which is replaced as a whole), with its header.
std::unique_ptr<io::AtomicFile> OpenTrace(const std::string& option, const std::string& path, const ReplayArgs& args,
                                          const io::ResultFolder* out, std::uintmax_t expected_bytes,
                                          const char* header) {
  if (path.empty()) return nullptr;
  if (out && io::IsInside(path, out->target())) {
    throw schema::InputError(option + " " + path + ": lies inside --out " + args.out +
                             ", which is replaced as a whole; put the trace beside it");
  }
  auto file = std::make_unique<io::AtomicFile>(path, args.overwrite, Inputs(args), expected_bytes);
  file->stream() << header << '\n';
  return file;
}

io::LogPolicy PolicyOf(const ReplayArgs& args) {
  io::LogPolicy policy = args.policy;
  policy.repeated_poses = io::RepeatedPosesFromName(args.repeated_poses);
  policy.out_of_order = io::OutOfOrderFromName(args.out_of_order);
  return policy;
}

}  // namespace

int ReplayCommand(const ReplayArgs& args, const AppContext& app) {
  schema::ExperimentConfig config;  // the defaults, unless --config names a file
  if (!args.config.empty()) config = config::LoadConfig(args.config, {}, app.components);
  if (args.navigate) {
    if (args.out.empty()) throw schema::InputError("--navigate: writes its tables into --out, which is not given");
    studies::CheckLogNavigation(config);
  }
  std::optional<std::map<int, schema::AnchorTruth>> truth;
  if (!args.anchors.empty()) truth = io::LoadAnchors(args.anchors);
  // The first pass: every file read to the end under the policy, so that a malformed file or a
  // refused row ends the command before any output exists.
  Progress checking("replay: checking", args.quiet, "MB", kBytesPerMb);
  const studies::ReplayLog replay({args.poses, args.ranges}, PolicyOf(args), std::move(truth), config, app.components,
                                 [&](std::uint64_t done, std::uint64_t total) { checking.Update(done, total); });
  if (!args.quiet && checking.elapsed_s() > 1.0) checking.Finish(static_cast<long long>(replay.survey().bytes));
  if (args.navigate) {
    studies::CheckErrorBins(replay.survey().t_last_pose_s - replay.survey().t_first_pose_s, *config.navigation,
                           args.poses);
  }

  // The outputs, before any work: never an input, never earlier results without --overwrite.
  std::unique_ptr<io::ResultFolder> out;
  if (!args.out.empty()) {
    io::ResultFolder::Options options;
    options.overwrite = args.overwrite;
    // With --navigate: ~150 bytes per (draw, method) and the error's bins.
    options.expected_bytes = (1 << 16) + (args.navigate ? 150u * static_cast<std::uintmax_t>(config.realizations) *
                                                              (config.estimator.triggers.size() + 2) : 0u);
    options.inputs = Inputs(args);
    out = std::make_unique<io::ResultFolder>(args.out, options);
  }
  if (!args.trace.empty() && !args.certificate_trace.empty() &&
      std::filesystem::weakly_canonical(args.trace) == std::filesystem::weakly_canonical(args.certificate_trace)) {
    throw schema::InputError("--certificate-trace " + args.certificate_trace + ": is also --trace");
  }
  constexpr std::uintmax_t kBytesPerTraceRow = 64, kBytesOfJudgements = 1 << 20;  // a geometric cadence: few
  const std::unique_ptr<io::AtomicFile> trace_file =
      OpenTrace("--trace", args.trace, args, out.get(),
                kBytesPerTraceRow * static_cast<std::uintmax_t>(replay.survey().range_rows), report::kTraceHeader);
  const std::unique_ptr<io::AtomicFile> certificate_file = OpenTrace(
      "--certificate-trace", args.certificate_trace, args, out.get(), kBytesOfJudgements, report::kJudgementColumns);
  studies::TraceSink trace;
  if (trace_file) {
    trace = [&](const io::RangeRecord& r, const estimator::FeedResult& fed) {
      report::WriteTraceRow(trace_file->stream(), r, fed);
    };
  }
  studies::JudgementSink judged;
  if (certificate_file) {
    judged = [&](int anchor_id, std::size_t trigger, const estimator::Judgement& judgement) {
      report::WriteJudgementRow(certificate_file->stream(), anchor_id, config.estimator.triggers[trigger], judgement);
    };
  }

  // The second pass, streamed: one row at a time from the files into the front end.
  Progress progress("replay", args.quiet, "MB", kBytesPerMb);
  const studies::ReplayOutcome outcome = replay.Run(trace, [&](std::uint64_t done, std::uint64_t total) {
    engine::ThrowIfStopped(app.stop);  // every 65,536 rows
    progress.Update(static_cast<long long>(done), static_cast<long long>(total));
  }, judged);
  if (progress.elapsed_s() > 1.0) progress.Finish(static_cast<long long>(replay.survey().bytes));

  if (!args.quiet) report::PrintReplaySummary(std::cerr, outcome.summary);
  report::PrintEstimates(std::cout, outcome.result.attempts);
  if (trace_file) trace_file->Commit();
  if (certificate_file) certificate_file->Commit();
  if (out) {
    const engine::FileWriter write = [&](const std::string& name, const std::function<void(std::ostream&)>& file) {
      out->Write(name, file);
    };
    studies::WriteReplayFiles(write, outcome);
    if (args.navigate) studies::WriteLogNavigation(write, replay, outcome, config, engine::ResolveThreads(0));
    out->Commit();
  }
  return 0;
}

}  // namespace anchorbench::app
