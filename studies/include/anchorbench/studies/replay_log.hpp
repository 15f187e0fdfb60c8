#pragma once
// `anchorbench replay` as one object, for the command line and the Python module alike: a
// recorded log checked in a first pass (every file read under the policy, the triggers built for
// every anchor) before any output exists, then replayed in a second, streamed pass, and its
// files written.

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "anchorbench/engine/commit.hpp"
#include "anchorbench/studies/replay.hpp"
#include "anchorbench/io/log_reader.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/report/replay_summary.hpp"
#include "anchorbench/schema/attempt.hpp"
#include "anchorbench/schema/experiment.hpp"

namespace anchorbench::studies {

struct ReplayOutcome {
  ReplayResult result;
  report::ReplaySummary summary;
};

class ReplayLog {
 public:
  // The first pass: throws InputError for a malformed file, a row the policy refuses, a trigger
  // that cannot run on this log (pdop_true without `truth`), or a `truth` that names none of the
  // anchors ranged. `progress` sees bytes read.
  ReplayLog(io::LogFiles files, io::LogPolicy policy, std::optional<std::map<int, schema::AnchorTruth>> truth,
            const schema::ExperimentConfig& config, const registry::Components& components,
            const io::ByteProgress& progress = nullptr);

  const io::LogSurvey& survey() const { return survey_; }
  const io::LogFiles& files() const { return files_; }
  const io::LogPolicy& policy() const { return policy_; }
  const std::map<int, schema::AnchorTruth>* truth() const { return truth_ ? &*truth_ : nullptr; }

  // The second pass, one row at a time into the front end; `trace` sees every range handed to
  // the initializers.
  ReplayOutcome Run(const TraceSink& trace = nullptr, const io::ByteProgress& progress = nullptr,
                    const JudgementSink& judged = nullptr) const;

 private:
  // Refuses a survey (--anchors) that names none of the anchors the log ranges.
  void CheckAnchorsMatch() const;

  io::LogFiles files_;
  io::LogPolicy policy_;
  std::optional<std::map<int, schema::AnchorTruth>> truth_;
  const schema::ExperimentConfig& config_;
  const registry::Components& components_;
  io::LogSurvey survey_;
};

// A replay's files: estimates.csv, replay_summary.json and replay_summary.md.
void WriteReplayFiles(const engine::FileWriter& write, const ReplayOutcome& outcome);

}  // namespace anchorbench::studies
