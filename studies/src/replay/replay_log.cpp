#include "anchorbench/studies/replay_log.hpp"

#include "anchorbench/io/recorded_data.hpp"
#include "anchorbench/report/replay_report.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::studies {

using engine::FileWriter;

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
  CheckAnchorsMatch();
}

void ReplayLog::CheckAnchorsMatch() const {
  // A survey that names none of the ranged anchors is another site's (or another numbering): every
  // error would be empty. Some surveyed anchors missing from the log, or the reverse, is normal.
  if (!truth_ || truth_->empty() || survey_.anchor_ids.empty()) return;
  for (const int anchor_id : survey_.anchor_ids) {
    if (truth_->contains(anchor_id)) return;
  }
  auto ids = [](auto first, auto last, std::size_t count) {
    return std::to_string(count) + " (ids " + std::to_string(first) + " to " + std::to_string(last) + ")";
  };
  throw schema::InputError("--anchors: none of its " +
                           ids(truth_->begin()->first, truth_->rbegin()->first, truth_->size()) +
                           " is an anchor the log ranges, " +
                           ids(*survey_.anchor_ids.begin(), *survey_.anchor_ids.rbegin(), survey_.anchor_ids.size()));
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

}  // namespace anchorbench::studies
