#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "anchorbench/experiments/anchor_bank.hpp"
#include "anchorbench/experiments/recorded_data.hpp"

namespace anchorbench::experiments {

struct ReplayResult {
  std::vector<AttemptOutcome> outcomes;
  int ranges_used = 0;
  int ranges_skipped = 0;       // outside their tag's pose time span (or a tag without poses)
  int first_skipped_line = 0;   // in ranges.csv
};

using TraceSink = std::function<void(const RangeRecord&, const estimator::FeedResult&)>;

// Runs the online initializers over recorded ranges in time order, tag positions interpolated at
// each range time. Ranges outside the pose span are skipped and counted, never extrapolated.
// `seed` keys the random parts of the estimator (RANSAC, stochastic NLopt) as in a simulation's
// realization 0. Throws InputError if a trigger cannot run (pdop_true without truth).
ReplayResult Replay(const PoseTracks& poses, const std::vector<RangeRecord>& ranges,
                    const std::map<int, AnchorTruth>* truth, const estimator::InitializerOptions& options,
                    const TraceSink& trace = nullptr, std::uint64_t seed = 1);

// Builds every anchor's initializers once, without data, so that what Replay would refuse (a
// trigger that needs the truth it lacks) is refused before any output exists. Throws InputError.
void CheckReplayable(const std::vector<RangeRecord>& ranges, const std::map<int, AnchorTruth>* truth,
                     const estimator::InitializerOptions& options);

// estimates.csv: anchor_id,method,initialized,t_init,n_used,pdop_est,pdop_true,x,y,z,bias,err_m
void WriteEstimates(std::ostream& out, const std::vector<AttemptOutcome>& outcomes);
// The same, aligned for a terminal.
void PrintEstimates(std::ostream& out, const std::vector<AttemptOutcome>& outcomes);

constexpr const char* kTraceHeader = "t,tag_id,anchor_id,range,accepted,n_accepted,pdop";
void WriteTraceRow(std::ostream& out, const RangeRecord& range, const estimator::FeedResult& fed);

}  // namespace anchorbench::experiments
