#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "anchorbench/estimator/anchor_initializer.hpp"
#include "anchorbench/eval/oracle_latency.hpp"
#include "anchorbench/schema/attempt.hpp"
#include "anchorbench/schema/random_streams.hpp"

namespace anchorbench::engine {

// The attempt of one of an anchor's initializers, after the end of data: `event` is its
// initialization (or its fixed-window solve), if any; `truth` (may be null) adds the evaluation.
schema::Attempt AttemptOf(const estimator::AnchorInitializer& initializer, const std::optional<estimator::InitEvent>& event,
                  const std::string& method, const schema::AnchorTruth* truth);

// The seed of anchor `anchor_id`'s random parts (RANSAC) in realization `realization`: drawn from
// the stream (seed, realization, schema::kSolverStream, anchor id), so it repeats for any thread count.
std::uint64_t SolverSeed(std::uint64_t seed, std::uint64_t realization, int anchor_id);

// The anchor's oracle time into an evaluated attempt, with the attempt's latency against it.
void AddOracleLatency(const eval::OracleLatency& oracle, schema::Attempt& attempt);

// The truth of one anchor, or nullptr.
const schema::AnchorTruth* TruthOf(const std::map<int, schema::AnchorTruth>* truth, int anchor_id);

}  // namespace anchorbench::engine
