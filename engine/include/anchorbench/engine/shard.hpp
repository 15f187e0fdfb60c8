#pragma once

#include <string>

namespace anchorbench::engine {

// A deterministic share of a plan's chunks (plan.hpp) for another process or machine: shard
// `index` of `count` takes the chunks with chunk % count == index (round robin, so every shard
// gets a share of every experiment and row). The shards of a run or sweep together hold every
// chunk exactly once; `anchorbench merge` joins them.
struct Shard {
  int index = 0;
  int count = 1;
  bool Holds(int chunk) const { return chunk % count == index; }
  int ChunksOf(int chunks) const { return chunks / count + (index < chunks % count ? 1 : 0); }
};

// "I/N" with 0 <= I < N <= 1e6; throws schema::InputError naming `what` otherwise.
Shard ParseShard(const std::string& text, const std::string& what);

}  // namespace anchorbench::engine
