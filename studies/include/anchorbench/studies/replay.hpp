#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "anchorbench/estimator/front_end.hpp"
#include "anchorbench/io/log_reader.hpp"
#include "anchorbench/io/recorded_data.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/engine/attempt.hpp"

namespace anchorbench::studies {

struct ReplayResult {
  std::vector<schema::Attempt> attempts;  // anchor ids ascending, triggers in list order
  estimator::FrontEndCounters counters;
  // Rows that never reached the initializers: the readers' drops and the front end's (outside
  // the tag's pose span, no pose in time), by anchor or tag and reason.
  io::LogDrops drops;
  std::map<int, std::int64_t> samples_by_anchor;  // ranges handed to the initializers
  double t_end_s = 0.0;  // the last of them: the end of the data, when the fixed window solves
};

// Sees every range handed to the initializers, with the first trigger's view of it.
using TraceSink = std::function<void(const io::RangeRecord&, const estimator::FeedResult&)>;
// Sees every evaluation of a trigger that solves (the certificate's tests, and why it waits), in
// the order they ran: the anchor, the trigger's index in the config's list, its judgement.
using JudgementSink = std::function<void(int anchor_id, std::size_t trigger, const estimator::Judgement&)>;
// The next row of a log in time order (a pose before a range of the same time); false at the end.
using LogSource = std::function<bool(io::RecordedLog::Kind&, io::PoseRecord&, io::RangeRecord&)>;

// Replays a recorded log through the online front end, as a navigation stack would see it, one
// row at a time: tag positions interpolated at each range time, ranges outside their tag's pose
// span dropped and counted, never extrapolated. `range_sources` names the ranges files in drop
// counts. Random parts are seeded as in a simulation's realization 0 with `seed`. Throws
// schema::InputError if a trigger cannot run (pdop_true without the truth).
ReplayResult Replay(const LogSource& log, const std::vector<std::string>& range_sources,
                    const std::map<int, schema::AnchorTruth>* truth, const schema::EstimatorConfig& config,
                    const registry::Components& components, std::uint64_t seed, const TraceSink& trace = nullptr,
                    const JudgementSink& judged = nullptr);

// The same on a log in memory: poses in any order (stably sorted by time), ranges in time order.
ReplayResult Replay(const std::vector<io::PoseRecord>& poses, const std::vector<io::RangeRecord>& ranges,
                    const std::map<int, schema::AnchorTruth>* truth, const schema::EstimatorConfig& config,
                    const registry::Components& components, std::uint64_t seed, const TraceSink& trace = nullptr,
                    const JudgementSink& judged = nullptr);

// Builds every anchor's initializers once, without data, so that what Replay would refuse (a
// trigger that needs the truth it lacks) is refused before any output exists. Throws InputError.
void CheckReplayable(const std::set<int>& anchor_ids, const std::map<int, schema::AnchorTruth>* truth,
                     const schema::EstimatorConfig& config, const registry::Components& components);

}  // namespace anchorbench::studies
