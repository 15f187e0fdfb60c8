#include "anchorbench/studies/replay.hpp"

#include <algorithm>
#include <deque>
#include <stdexcept>

#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::studies {

using engine::AddOracleLatency;
using engine::AttemptOf;
using engine::SolverSeed;
using engine::TruthOf;
namespace {

// The config's chains, and where the anchor's survey is known the oracle's (eval/oracle_latency.hpp)
// after them, logging into `oracle_logs` (if given).
estimator::FrontEnd::ChainFactory ChainsFor(const std::map<int, schema::AnchorTruth>* truth,
                                            const schema::EstimatorConfig& config,
                                            const registry::Components& components, std::uint64_t seed,
                                            std::map<int, std::shared_ptr<eval::OracleLog>>* oracle_logs = nullptr) {
  return [=, &config, &components](int anchor_id) {
    const schema::AnchorTruth* known = TruthOf(truth, anchor_id);
    try {
      std::vector<estimator::AnchorInitializer> chains =
          registry::MakeChains(components, anchor_id, config, SolverSeed(seed, 0, anchor_id),
                               known ? std::optional(known->p_world_anchor) : std::nullopt);
      if (known && oracle_logs) {
        auto& log = (*oracle_logs)[anchor_id] = std::make_shared<eval::OracleLog>();
        chains.push_back(eval::MakeOracleChain(components, anchor_id, config, SolverSeed(seed, 0, anchor_id),
                                               known->p_world_anchor, log));
      }
      return chains;
    } catch (const std::invalid_argument& e) {
      throw schema::InputError("anchor " + std::to_string(anchor_id) + ": " + e.what());
    }
  };
}

io::Drop DropReasonOf(estimator::DroppedRange::Reason reason) {
  switch (reason) {
    case estimator::DroppedRange::Reason::kOutsidePoses: return io::Drop::kOutsidePoses;
    case estimator::DroppedRange::Reason::kNoPoseInTime: return io::Drop::kNoPoseInTime;
    case estimator::DroppedRange::Reason::kTooManyAnchors: return io::Drop::kTooManyAnchors;
  }
  return io::Drop::kNoPoseInTime;
}

static_assert(io::LogPolicy{}.max_anchors == estimator::FrontEndOptions{}.max_anchors,
              "replay refuses a log of more anchors than the front end takes");

}  // namespace

ReplayResult Replay(const LogSource& log, const std::vector<std::string>& range_sources,
                    const std::map<int, schema::AnchorTruth>* truth, const schema::EstimatorConfig& config,
                    const registry::Components& components, std::uint64_t seed, const TraceSink& trace,
                    const JudgementSink& judged) {
  ReplayResult result;
  std::map<int, std::shared_ptr<eval::OracleLog>> oracle_logs;
  estimator::FrontEndOptions options;
  options.report_judgements = static_cast<bool>(judged);
  estimator::FrontEnd front_end(
      ChainsFor(truth, config, components, seed, config.oracle_latency ? &oracle_logs : nullptr), options);
  // Initializations are kept for the end; judgements go to `judged` as they come (the oracle's
  // chain, after the config's, is not reported).
  std::map<std::pair<int, std::size_t>, estimator::InitEvent> events;
  auto take_events = [&] {
    for (estimator::FrontEndEvent& event : front_end.TakeEvents()) {
      if (event.kind == estimator::FrontEndEvent::Kind::kJudged) {
        if (event.chain < config.triggers.size()) judged(event.anchor_id, event.chain, event.judgement);
      } else {
        events[{event.anchor_id, event.chain}] = event.init;
      }
    }
  };
  // Ranges leave the front end's queue in the order they went in, used or dropped: the oldest
  // range in flight is the one leaving. The queue is bounded (FrontEndOptions), so is this.
  std::deque<io::RangeRecord> in_flight;
  const std::string unnamed = "ranges";
  auto source_of = [&](const io::RangeRecord& r) -> const std::string& {
    return r.file >= 0 && static_cast<std::size_t>(r.file) < range_sources.size()
               ? range_sources[static_cast<std::size_t>(r.file)]
               : unnamed;
  };
  front_end.SetSampleObserver([&](const estimator::RangeSample& sample, const estimator::FeedResult& fed) {
    ++result.samples_by_anchor[sample.anchor_id];
    if (trace) trace(in_flight.front(), fed);
    in_flight.pop_front();
  });
  front_end.SetDropObserver([&](const estimator::DroppedRange& dropped) {
    const io::RangeRecord& r = in_flight.front();
    result.drops.Count(DropReasonOf(dropped.reason), r.anchor_id, source_of(r), r.line);
    in_flight.pop_front();
  });
  io::RecordedLog::Kind kind;
  io::PoseRecord pose;
  io::RangeRecord range;
  while (log(kind, pose, range)) {
    if (kind == io::RecordedLog::Kind::kPose) {
      front_end.AddPose(pose.t_s, pose.tag_id, pose.p_world_tag);
    } else {
      in_flight.push_back(range);
      front_end.AddRange(range.t_s, range.tag_id, range.anchor_id, range.range_m);
      if (judged) take_events();  // bounded: the events since the last range
    }
  }
  front_end.Finish(front_end.t_last_sample_s());
  take_events();
  const double t_end_s = front_end.t_last_sample_s();
  result.t_end_s = t_end_s;
  for (int anchor_id : front_end.anchor_ids()) {
    const std::vector<estimator::AnchorInitializer>& chains = front_end.chains(anchor_id);
    std::optional<eval::OracleLatency> oracle;
    if (const auto log = oracle_logs.find(anchor_id); log != oracle_logs.end()) {
      oracle = eval::OracleOf(chains.back(), *log->second, config.certificate.accuracy_m,
                              truth->at(anchor_id).p_world_anchor, t_end_s);
    }
    for (std::size_t c = 0; c < config.triggers.size(); ++c) {
      const auto event = events.find({anchor_id, c});
      result.attempts.push_back(AttemptOf(chains[c], event == events.end() ? std::nullopt : std::optional(event->second),
                                          config.triggers[c], TruthOf(truth, anchor_id)));
      if (oracle) AddOracleLatency(*oracle, result.attempts.back());
    }
  }
  result.counters = front_end.counters();
  return result;
}

ReplayResult Replay(const std::vector<io::PoseRecord>& poses, const std::vector<io::RangeRecord>& ranges,
                    const std::map<int, schema::AnchorTruth>* truth, const schema::EstimatorConfig& config,
                    const registry::Components& components, std::uint64_t seed, const TraceSink& trace,
                    const JudgementSink& judged) {
  std::vector<io::PoseRecord> by_time = poses;
  std::stable_sort(by_time.begin(), by_time.end(),
                   [](const io::PoseRecord& a, const io::PoseRecord& b) { return a.t_s < b.t_s; });
  std::size_t i = 0, j = 0;
  const LogSource merged = [&](io::RecordedLog::Kind& kind, io::PoseRecord& pose, io::RangeRecord& range) {
    if (i == by_time.size() && j == ranges.size()) return false;
    if (j == ranges.size() || (i < by_time.size() && by_time[i].t_s <= ranges[j].t_s)) {
      kind = io::RecordedLog::Kind::kPose;
      pose = by_time[i++];
    } else {
      kind = io::RecordedLog::Kind::kRange;
      range = ranges[j++];
    }
    return true;
  };
  return Replay(merged, {}, truth, config, components, seed, trace, judged);
}

void CheckReplayable(const std::set<int>& anchor_ids, const std::map<int, schema::AnchorTruth>* truth,
                     const schema::EstimatorConfig& config, const registry::Components& components) {
  estimator::FrontEnd front_end(ChainsFor(truth, config, components, 0));
  for (int anchor_id : anchor_ids) front_end.AddAnchor(anchor_id);
}

}  // namespace anchorbench::studies
