#pragma once

#include <string>

namespace anchorbench::runner {

// A deterministic share of a run's work units for another process or machine: the units are
// (row, realization) numbered row x realizations + realization, and shard `index` of `count`
// takes those with unit % count == index (round robin, so every shard gets a share of every row).
// The shards of a run together hold every unit exactly once; `anchorbench merge` joins them.
struct Shard {
  int index = 0;
  int count = 1;
  bool Holds(int unit) const { return unit % count == index; }
  int UnitsOf(int units) const { return units / count + (index < units % count ? 1 : 0); }
};

// "I/N" with 0 <= I < N <= 1e6; throws io::InputError naming `what` otherwise.
Shard ParseShard(const std::string& text, const std::string& what);

}  // namespace anchorbench::runner
