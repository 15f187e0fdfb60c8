#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <vector>

#include "anchorbench/estimator/front_end.hpp"
#include "anchorbench/io/recorded_data.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/runner/attempt.hpp"

namespace anchorbench::runner {

struct ReplayResult {
  std::vector<Attempt> attempts;  // anchor ids ascending, triggers in list order
  estimator::FrontEndCounters counters;
  int ranges_skipped = 0;      // outside their tag's pose time span (or a tag without poses)
  int first_skipped_line = 0;  // in ranges.csv
};

// Sees every range handed to the initializers, with the first trigger's view of it.
using TraceSink = std::function<void(const io::RangeRecord&, const estimator::FeedResult&)>;

// Replays a recorded log through the online front end, as a navigation stack would see it: poses
// and ranges merged in time order (a pose before a range of the same time), tag positions
// interpolated at each range time. Ranges outside their tag's pose span are skipped and counted,
// never extrapolated. Random parts are seeded as in a simulation's realization 0 with `seed`.
// Throws io::InputError if a trigger cannot run (pdop_true without the truth).
ReplayResult Replay(const std::vector<io::PoseRecord>& poses, const std::vector<io::RangeRecord>& ranges,
                    const std::map<int, eval::AnchorTruth>* truth, const registry::EstimatorConfig& config,
                    const registry::Components& components, std::uint64_t seed, const TraceSink& trace = nullptr);

// Builds every anchor's initializers once, without data, so that what Replay would refuse (a
// trigger that needs the truth it lacks) is refused before any output exists. Throws InputError.
void CheckReplayable(const std::vector<io::RangeRecord>& ranges, const std::map<int, eval::AnchorTruth>* truth,
                     const registry::EstimatorConfig& config, const registry::Components& components);

}  // namespace anchorbench::runner
