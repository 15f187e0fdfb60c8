#pragma once
// The navigation study on a recorded log (anchorbench replay --navigate; docs/navigation.md). The
// log's poses of one tag are the truth and its ranges are the filter's; the odometry is
// synthetic: drawn from those poses with the seeded random walks of the config's `navigation`
// section, as in simulation. The triggers' anchors are the replay's.

#include <cstdint>
#include <map>
#include <vector>

#include "anchorbench/studies/navigation.hpp"
#include "anchorbench/studies/replay_log.hpp"
#include "anchorbench/io/log_reader.hpp"
#include "anchorbench/schema/attempt.hpp"
#include "anchorbench/schema/experiment.hpp"

namespace anchorbench::studies {

struct LogTrajectory {
  int tag_id = 0;
  Trajectory run;               // each range at the epoch of the tag's last pose at or before it
  std::int64_t repeated_poses = 0;  // a pose at its predecessor's time (or before): not an epoch
  std::int64_t ranges_outside = 0;  // before the tag's first pose or after its last: not used
};

// The survey's lowest tag, read in one more pass under `policy`. Throws InputError if it has fewer
// than two poses.
LogTrajectory ReadLogTrajectory(const io::LogFiles& files, const io::LogPolicy& policy, const io::LogSurvey& survey);

// Refuses (InputError) a config without a `navigation` section or without its sigma_range_m (a
// log has no simulated row whose noise the filter could assume).
void CheckLogNavigation(const schema::ExperimentConfig& config);

// config.realizations draws of the odometry (draw r from the stream (seed, r, kNavigationStream)),
// each with the replay's triggers, the true anchors (if `truth`; its bias 0 where it has none)
// and none, on `threads` threads; the same records for any thread count. Row 0. `t_end_s`: the
// replay's last sample, when the fixed window's anchors become usable.
std::vector<NavigationRecord> NavigateLog(const LogTrajectory& log, const std::vector<schema::Attempt>& attempts,
                                          double t_end_s, const std::map<int, schema::AnchorTruth>* truth,
                                          const schema::ExperimentConfig& config, int threads);

// `replay --navigate` after the replay: the log's trajectory read (ReadLogTrajectory), navigated
// with the outcome's anchors (NavigateLog), and its tables written through `write`, their one
// row named by the tag (WriteNavigationTables).
void WriteLogNavigation(const engine::FileWriter& write, const ReplayLog& replay, const ReplayOutcome& outcome,
                        const schema::ExperimentConfig& config, int threads);

}  // namespace anchorbench::studies
