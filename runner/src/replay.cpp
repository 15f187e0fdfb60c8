#include "anchorbench/runner/replay.hpp"

#include <algorithm>
#include <stdexcept>

#include "anchorbench/io/input_error.hpp"

namespace anchorbench::runner {
namespace {

estimator::FrontEnd::ChainFactory ChainsFor(const std::map<int, eval::AnchorTruth>* truth,
                                            const registry::EstimatorConfig& config,
                                            const registry::Components& components, std::uint64_t seed) {
  return [=, &config, &components](int anchor_id) {
    const eval::AnchorTruth* known = TruthOf(truth, anchor_id);
    try {
      return registry::MakeChains(components, anchor_id, config, SolverSeed(seed, 0, anchor_id),
                                  known ? std::optional(known->p_world_anchor) : std::nullopt);
    } catch (const std::invalid_argument& e) {
      throw io::InputError("anchor " + std::to_string(anchor_id) + ": " + e.what());
    }
  };
}

// Poses and ranges into the front end in time order, poses first at equal times.
void FeedInTimeOrder(std::vector<io::PoseRecord> poses, const std::vector<io::RangeRecord>& ranges,
                     estimator::FrontEnd& front_end) {
  std::stable_sort(poses.begin(), poses.end(),
                   [](const io::PoseRecord& a, const io::PoseRecord& b) { return a.t_s < b.t_s; });
  std::size_t i = 0, j = 0;
  while (i < poses.size() || j < ranges.size()) {
    if (j == ranges.size() || (i < poses.size() && poses[i].t_s <= ranges[j].t_s)) {
      front_end.AddPose(poses[i].t_s, poses[i].tag_id, poses[i].p_world_tag);
      ++i;
    } else {
      front_end.AddRange(ranges[j].t_s, ranges[j].tag_id, ranges[j].anchor_id, ranges[j].range_m);
      ++j;
    }
  }
}

}  // namespace

ReplayResult Replay(const std::vector<io::PoseRecord>& poses, const std::vector<io::RangeRecord>& ranges,
                    const std::map<int, eval::AnchorTruth>* truth, const registry::EstimatorConfig& config,
                    const registry::Components& components, std::uint64_t seed, const TraceSink& trace) {
  ReplayResult result;
  estimator::FrontEnd front_end(ChainsFor(truth, config, components, seed));
  // Ranges leave the front end's queue in the order they went in, used or dropped: the n-th to
  // leave is ranges[n].
  std::size_t left = 0;
  front_end.SetSampleObserver([&](const estimator::RangeSample&, const estimator::FeedResult& fed) {
    if (trace) trace(ranges[left], fed);
    ++left;
  });
  front_end.SetDropObserver([&](const estimator::DroppedRange&) {
    if (result.ranges_skipped++ == 0) result.first_skipped_line = ranges[left].line;
    ++left;
  });
  FeedInTimeOrder(poses, ranges, front_end);
  front_end.Finish(front_end.t_last_sample_s());

  std::map<std::pair<int, std::size_t>, estimator::InitEvent> events;
  for (const estimator::FrontEndEvent& event : front_end.TakeEvents()) events[{event.anchor_id, event.chain}] = event.init;
  for (int anchor_id : front_end.anchor_ids()) {
    const std::vector<estimator::AnchorInitializer>& chains = front_end.chains(anchor_id);
    for (std::size_t c = 0; c < chains.size(); ++c) {
      const auto event = events.find({anchor_id, c});
      result.attempts.push_back(AttemptOf(chains[c], event == events.end() ? std::nullopt : std::optional(event->second),
                                          config.triggers[c], TruthOf(truth, anchor_id)));
    }
  }
  result.counters = front_end.counters();
  return result;
}

void CheckReplayable(const std::vector<io::RangeRecord>& ranges, const std::map<int, eval::AnchorTruth>* truth,
                     const registry::EstimatorConfig& config, const registry::Components& components) {
  estimator::FrontEnd front_end(ChainsFor(truth, config, components, 0));
  for (const io::RangeRecord& range : ranges) front_end.AddAnchor(range.anchor_id);
}

}  // namespace anchorbench::runner
