#pragma once

#include <cstdint>

#include "anchorbench/sim/random_stream.hpp"

namespace anchorbench::schema {

// The random streams drawn outside the simulator, in one table (sim::StreamId has the simulator's).
constexpr std::uint32_t kSolverStream = 8;     // an anchor's random parts (RANSAC), engine::SolverSeed
constexpr std::uint32_t kBootstrapStream = 9;  // the realization bootstrap of summary.csv, report::Summarize
constexpr std::uint32_t kNavigationStream = 10;  // a realization's odometry drift, studies::NavigateRealization
static_assert(kSolverStream >= sim::kFirstFreeStreamId && kBootstrapStream >= sim::kFirstFreeStreamId &&
                  kNavigationStream >= sim::kFirstFreeStreamId && kSolverStream != kBootstrapStream &&
                  kNavigationStream != kSolverStream && kNavigationStream != kBootstrapStream,
              "stream ids below kFirstFreeStreamId are the simulator's; each id has one owner");

}  // namespace anchorbench::schema
