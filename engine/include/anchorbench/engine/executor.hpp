#pragma once
// Who computes a plan's chunks, and a study's record units. The commands hand an Executor the
// chunks (or units) still to compute and take each one back through a callback; this process's
// threads (LocalExecutor) and the ranks of an MPI job (app's MpiExecutor) are interchangeable
// because a chunk's bytes, or a unit's text, do not depend on either.

#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "anchorbench/registry/components.hpp"
#include "anchorbench/engine/chunk.hpp"
#include "anchorbench/engine/plan.hpp"
#include "anchorbench/engine/run_control.hpp"

namespace anchorbench::engine {

// Called once per chunk, from one thread at a time, in no particular order: the chunk's index,
// its result and its text (ChunkText).
using ChunkDone = std::function<void(int chunk, ChunkResult&& result, const std::string& text)>;

// A study of record units (unit_records.hpp) as an executor sees it: the study's name and the plan
// of its one config (what a worker rank rebuilds the study from), and how this process computes
// one unit's text.
struct UnitWork {
  std::string study;
  const Plan* plan = nullptr;
  std::function<std::string(int unit)> text_of;
};

// Called once per unit, from one thread at a time, in no particular order: the unit and its text.
using UnitDone = std::function<void(int unit, std::string&& text)>;

class Executor {
 public:
  virtual ~Executor() = default;
  // Computes `chunks` (indices into plan.chunks()) with `threads` threads per process. An error
  // in any chunk, or thrown by `done` (a chunk that cannot be stored), ends the call with that
  // error (schema::InputError for bad input): chunks not yet started are skipped, and `done` has seen
  // every chunk that finished.
  virtual void Compute(const Plan& plan, const std::vector<int>& chunks, int threads, const ChunkDone& done) = 0;
  // The same for `units` of a study of record units, with the same guarantees; by default on this
  // process's threads (ComputeUnitsHere).
  virtual void ComputeUnits(const UnitWork& work, const std::vector<int>& units, int threads, const UnitDone& done);
};

// work(item, thread) for every item in [0, count) on `threads` OpenMP threads, one item per
// thread at a time, dynamically scheduled; `thread` in [0, threads) indexes per-thread scratch.
// An exception stops the items after it from starting (the earlier ones still run, so the first
// throwing item always runs), and the first one in item order is rethrown once the threads are
// done, whatever the timing. With `stop` set, no new item starts either, and
// the loop ends in Interrupted. The one parallel loop of the engine.
void ParallelFor(int count, int threads, const std::function<void(int item, int thread)>& work,
                 const StopFlag* stop = nullptr);

// work.text_of(unit) for each of `units` on `threads` threads (ParallelFor), handed to `done` one at
// a time: what an executor does with units on this process's threads.
void ComputeUnitsHere(const UnitWork& work, const std::vector<int>& units, int threads, const UnitDone& done,
                      const StopFlag* stop);

// `units` units on `threads` threads (ParallelFor), each giving its records, joined in unit order:
// the same for any thread count. `control` sees every unit done, and may stop the rest.
template <typename Record>
std::vector<Record> ParallelRecords(int units, int threads, const std::function<std::vector<Record>(int unit)>& unit,
                                    const RunControl& control) {
  std::vector<std::vector<Record>> by_unit(static_cast<std::size_t>(units));
  std::mutex progress_mutex;
  long long done = 0;
  if (control.progress) control.progress(0, units);
  ParallelFor(units, threads, [&](int u, int) {
    by_unit[static_cast<std::size_t>(u)] = unit(u);
    if (!control.progress) return;
    const std::lock_guard<std::mutex> lock(progress_mutex);
    control.progress(++done, units);
  }, control.stop);
  std::vector<Record> records;
  for (std::vector<Record>& records_of_unit : by_unit) {
    for (Record& r : records_of_unit) records.push_back(std::move(r));
  }
  return records;
}

// This process's threads (OpenMP), one chunk per thread at a time, dynamically scheduled; with
// `stop`, checked before every unit (run_control.hpp).
class LocalExecutor final : public Executor {
 public:
  explicit LocalExecutor(const registry::Components& components, const StopFlag* stop = nullptr)
      : components_(components), stop_(stop) {}
  void Compute(const Plan& plan, const std::vector<int>& chunks, int threads, const ChunkDone& done) override;
  void ComputeUnits(const UnitWork& work, const std::vector<int>& units, int threads, const UnitDone& done) override {
    ComputeUnitsHere(work, units, threads, done, stop_);
  }

 private:
  const registry::Components& components_;
  const StopFlag* stop_;
};

}  // namespace anchorbench::engine
