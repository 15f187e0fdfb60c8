#pragma once
// The work of one command as numbered chunks. A run is one experiment, a sweep one per grid point;
// each experiment's (row, realization) units, numbered row x realizations + realization, are cut
// into chunks of consecutive units. Chunks are what threads, MPI ranks and the chunk store deal
// in: a chunk's attempts depend on the plan alone, never on who computed them or when.

#include <string>
#include <vector>

#include "anchorbench/registry/components.hpp"
#include "anchorbench/schema/experiment.hpp"

namespace anchorbench::engine {

// Units [first_unit, end_unit) of one experiment, and the attempts they make (one per anchor and
// trigger of a unit's row).
struct ChunkSpan {
  int experiment = 0;
  int first_unit = 0;
  int end_unit = 0;
  long long attempts = 0;
};

// An experiment of U units is cut into chunks of ceil(U / kChunksPerExperiment) units, at most
// kMaxChunkUnits: ~256 chunks give 8 shards or 32 workers' threads enough chunks each that the
// last one's wait stays small, and a 1e6-unit sweep still hands out chunks of seconds, not hours.
// Smaller chunks cost more than they balance (each is a message, a block of the store, a text
// with its own header: Table I as 400 one-unit chunks ran ~20% slower than as 200 of two, when
// each was a file; docs/cluster.md). The size
// follows from the config alone, so a resumed run or another rank count cuts the same chunks.
constexpr int kChunksPerExperiment = 256;
constexpr int kMaxChunkUnits = 64;

class Plan {
 public:
  // `experiments` must have passed CheckExperiment (monte_carlo.hpp).
  explicit Plan(std::vector<schema::ExperimentConfig> experiments);

  const std::vector<schema::ExperimentConfig>& experiments() const { return experiments_; }
  const std::vector<schema::RowConfig>& rows(int experiment) const {
    return rows_[static_cast<std::size_t>(experiment)];
  }
  const std::vector<ChunkSpan>& chunks() const { return chunks_; }
  long long units() const { return units_; }
  long long attempts() const { return attempts_; }
  // Every experiment's resolved config (config::ToYaml), in order: what a worker rank rebuilds
  // the plan from (config::LoadConfigText) ...
  const std::vector<std::string>& texts() const { return texts_; }
  // ... and their fingerprint (io::Fingerprint): what a chunk store and a worker check.
  const std::string& identity() const { return identity_; }

 private:
  std::vector<schema::ExperimentConfig> experiments_;
  std::vector<std::vector<schema::RowConfig>> rows_;
  std::vector<ChunkSpan> chunks_;
  long long units_ = 0;
  long long attempts_ = 0;
  std::vector<std::string> texts_;
  std::string identity_;
};

// A plan from the texts of another plan (a worker rank's copy); refuses (schema::InputError) texts
// whose configs do not write back to the same identity.
Plan PlanFromTexts(const std::vector<std::string>& texts, const std::string& identity,
                   const registry::Components& components);

}  // namespace anchorbench::engine
