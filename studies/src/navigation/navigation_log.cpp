#include "anchorbench/studies/navigation_log.hpp"

#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/schema/random_streams.hpp"

namespace anchorbench::studies {

using engine::FileWriter;

LogTrajectory ReadLogTrajectory(const io::LogFiles& files, const io::LogPolicy& policy, const io::LogSurvey& survey) {
  LogTrajectory log;
  if (!survey.tag_ids.empty()) log.tag_id = *survey.tag_ids.begin();
  io::LogDrops drops;  // the replay's pass counted them already
  io::RecordedLog rows(files, policy, survey.default_tag_id, drops);
  io::RecordedLog::Kind kind;
  io::PoseRecord pose;
  io::RangeRecord range;
  std::vector<double> range_t_s;  // to drop the ranges after the last pose once it is known
  Trajectory& run = log.run;
  while (rows.Next(kind, pose, range)) {
    if (kind == io::RecordedLog::Kind::kPose) {
      if (pose.tag_id != log.tag_id) continue;
      if (!run.t_s.empty() && !(pose.t_s > run.t_s.back())) {
        ++log.repeated_poses;
        continue;
      }
      run.t_s.push_back(pose.t_s);
      run.p_world_tag.push_back(pose.p_world_tag);
    } else if (range.tag_id == log.tag_id) {
      if (run.t_s.empty()) {
        ++log.ranges_outside;
        continue;
      }
      run.ranges.push_back({run.t_s.size() - 1, range.anchor_id, range.range_m});
      range_t_s.push_back(range.t_s);
    }
  }
  if (run.t_s.size() < 2) {
    throw schema::InputError(files.poses + ": tag " + std::to_string(log.tag_id) +
                             " has fewer than two poses: no trajectory to navigate");
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < run.ranges.size(); ++i) {
    if (range_t_s[i] <= run.t_s.back()) run.ranges[kept++] = run.ranges[i];
  }
  log.ranges_outside += static_cast<std::int64_t>(run.ranges.size() - kept);
  run.ranges.resize(kept);
  return log;
}

void CheckLogNavigation(const schema::ExperimentConfig& config) {
  const std::string name = config.name.empty() ? "the default config" : config.name;
  if (!config.navigation) {
    throw schema::InputError(name + ": --navigate needs a 'navigation' section: nothing says how the synthetic "
                                    "odometry drifts (docs/navigation.md)");
  }
  if (!(config.navigation->sigma_range_m > 0.0)) {
    throw schema::InputError(name + ": key 'navigation.sigma_range_m': must be set (> 0) for a recorded log, which "
                                    "has no simulated noise the filter could assume");
  }
}

std::vector<NavigationRecord> NavigateLog(const LogTrajectory& log, const std::vector<schema::Attempt>& attempts,
                                          double t_end_s,
                                          const std::map<int, schema::AnchorTruth>* truth,
                                          const schema::ExperimentConfig& config, int threads) {
  CheckLogNavigation(config);
  const schema::NavigationConfig& navigation = *config.navigation;
  CheckErrorBins(log.run.t_s.back() - log.run.t_s.front(), navigation, config.name);
  std::vector<MethodAnchors> methods =
      TriggerAnchors(attempts, config.estimator.triggers, navigation.height_unobservable, t_end_s);
  if (truth) {
    std::vector<nav::UsableAnchor> anchors;
    for (const auto& [id, anchor] : *truth) {
      anchors.push_back({id, log.run.t_s.front(), anchor.p_world_anchor, anchor.bias_m.value_or(0.0),
                         Eigen::Matrix4d::Zero()});
    }
    methods.push_back({kTrueAnchors, std::move(anchors)});
  }
  methods.push_back({kNoAnchors, {}});
  const nav::NavigationOptions options = OptionsOf(navigation, navigation.sigma_range_m);
  return NavigateUnits(config.realizations, threads, [&](int draw) {
    sim::RandomStream rng(config.seed, static_cast<std::uint64_t>(draw), schema::kNavigationStream);
    return NavigateMethods(log.run, methods, options, rng, 0, draw);
  });
}

void WriteLogNavigation(const FileWriter& write, const ReplayLog& replay, const ReplayOutcome& outcome,
                        const schema::ExperimentConfig& config, int threads) {
  const LogTrajectory log = ReadLogTrajectory(replay.files(), replay.policy(), replay.survey());
  const std::vector<NavigationRecord> records =
      NavigateLog(log, outcome.result.attempts, outcome.result.t_end_s, replay.truth(), config, threads);
  const schema::RowConfig row{"tag_" + std::to_string(log.tag_id), {}, {}, std::nullopt};
  WriteNavigationTables(write, config, {row}, records);
}

}  // namespace anchorbench::studies
