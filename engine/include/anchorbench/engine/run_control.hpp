#pragma once
// What the caller of a long computation may ask of it while it runs: to stop. The Python front
// sets the flag on Ctrl-C; the command line, which a signal ends, leaves it unset.

#include <atomic>
#include <functional>
#include <stdexcept>

namespace anchorbench::engine {

// Set from any thread: no new unit starts, and the computation ends by throwing Interrupted once
// the units running have finished (a unit is one realization: well under a second at the
// committed sizes).
using StopFlag = std::atomic<bool>;

class Interrupted : public std::runtime_error {
 public:
  Interrupted() : std::runtime_error("interrupted") {}
};

// A long computation's progress, (units done, units in all), reported from one thread at a
// time, and its stop flag.
struct RunControl {
  std::function<void(long long done, long long total)> progress;
  const StopFlag* stop = nullptr;
};

inline void ThrowIfStopped(const StopFlag* stop) {
  if (stop && stop->load(std::memory_order_relaxed)) throw Interrupted();
}

}  // namespace anchorbench::engine
