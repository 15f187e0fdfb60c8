#pragma once
// anchorbench-mpi: the same commands over the ranks of an MPI job (mpirun -n K anchorbench-mpi
// run ...). Rank 0 runs the command as the plain binary would and hands out chunks of the plan
// (engine/plan.hpp), or units of navigate's and explore's studies, to the other ranks as they ask
// for more; the others only compute, so they read no file and write none. A chunk's bytes, or a
// unit's text, do not depend on who computed it, so the results are the plain binary's, byte for
// byte, for any K and any thread count (docs/cluster.md).

#include <functional>
#include <string>
#include <vector>

#include "anchorbench/registry/components.hpp"
#include "anchorbench/engine/executor.hpp"

namespace anchorbench::app {

// Rank 0's executor: K-1 worker ranks of `threads` threads each; every thread asks rank 0 for one
// chunk at a time (the next with each result), so a slow rank or thread holds only its own chunk.
// With no worker (-n 1) it computes on its own threads.
class MpiExecutor final : public engine::Executor {
 public:
  MpiExecutor(const registry::Components& components, int ranks, const engine::StopFlag* stop)
      : local_(components, stop), ranks_(ranks), stop_(stop) {}
  void Compute(const engine::Plan& plan, const std::vector<int>& chunks, int threads, const engine::ChunkDone& done) override;
  void ComputeUnits(const engine::UnitWork& work, const std::vector<int>& units, int threads,
                    const engine::UnitDone& done) override;
  // Whether workers hold chunks of a Compute that did not end (an error mid-plan).
  bool busy() const { return busy_; }

 private:
  // A result's fields (thread, item, then its texts) and the rank that sent it.
  using Take = std::function<void(std::vector<std::string>& fields, const std::string& rank)>;
  // Hands `items` (chunks of `plan`, or units of `study`) to the workers' threads as they ask, and
  // each result to `take`: the one dispatch loop of both.
  void HandOut(const engine::Plan& plan, const std::string& study, const std::vector<int>& items, int threads,
               const Take& take);

  engine::LocalExecutor local_;
  int ranks_;
  const engine::StopFlag* stop_;  // checked by rank 0 at every message: a signal ends the job there
  std::string plan_sent_;  // the plan the workers hold
  bool busy_ = false;
};

// The job around one process: MPI_Init on construction; on rank 0, Finish(exit code) ends it
// (stops the workers, or aborts the job if they are mid-plan: an error never hangs, and no rank
// goes on alone); on the others, Serve() computes chunks and units until rank 0 says stop.
class MpiJob {
 public:
  MpiJob(int& argc, char**& argv, const registry::Components& components);
  MpiJob(const MpiJob&) = delete;
  MpiJob& operator=(const MpiJob&) = delete;
  bool worker() const { return rank_ != 0; }
  engine::Executor& executor() { return executor_; }
  int Serve();
  int Finish(int exit_code);

 private:
  static int Init(int& argc, char**& argv, int& rank);  // MPI_Init; the rank count

  const registry::Components& components_;
  int rank_ = 0;
  int ranks_ = 1;
  MpiExecutor executor_;
};

}  // namespace anchorbench::app
