#include "anchorbench/engine/replay_log.hpp"

#include "anchorbench/io/recorded_data.hpp"
#include "anchorbench/report/replay_report.hpp"

namespace anchorbench::engine {

ReplayLog::ReplayLog(io::LogFiles files, io::LogPolicy policy, std::optional<std::map<int, schema::AnchorTruth>> truth,
                     const schema::ExperimentConfig& config, const registry::Components& components,
                     const io::ByteProgress& progress)
    : files_(std::move(files)),
      policy_(policy),
      truth_(std::move(truth)),
      config_(config),
      components_(components),
      survey_(io::SurveyLog(files_, policy_, progress)) {
  CheckReplayable(survey_.anchor_ids, truth_ ? &*truth_ : nullptr, config_.estimator, components_);
}

ReplayOutcome ReplayLog::Run(const TraceSink& trace, const io::ByteProgress& progress,
                             const JudgementSink& judged) const {
  ReplayOutcome outcome;
  outcome.summary = {files_, policy_, survey_.pose_rows, survey_.range_rows, {}, {}, survey_.reordered_rows};
  io::RecordedLog log(files_, policy_, survey_.default_tag_id, outcome.summary.drops);
  std::int64_t rows = 0;
  const LogSource source = [&](io::RecordedLog::Kind& kind, io::PoseRecord& pose, io::RangeRecord& range) {
    if (progress && (++rows & 0xffff) == 0) progress(log.bytes_read(), survey_.bytes);
    return log.Next(kind, pose, range);
  };
  outcome.result = Replay(source, files_.ranges, truth_ ? &*truth_ : nullptr, config_.estimator, components_,
                          config_.seed, trace, judged);
  outcome.summary.drops.Add(outcome.result.drops);
  outcome.summary.samples_by_anchor = outcome.result.samples_by_anchor;
  return outcome;
}

void WriteReplayFiles(const FileWriter& write, const ReplayOutcome& outcome) {
  write("estimates.csv", [&](std::ostream& file) { report::WriteEstimates(file, outcome.result.attempts); });
  write("replay_summary.json", [&](std::ostream& file) { report::WriteReplaySummaryJson(file, outcome.summary); });
  write("replay_summary.md", [&](std::ostream& file) { report::WriteReplaySummaryMarkdown(file, outcome.summary); });
}

}  // namespace anchorbench::engine
