#pragma once
// One chunk's attempts, computed or read back, and the text they travel and rest in.

#include <string>
#include <vector>

#include "anchorbench/estimator/range_sample.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/runner/attempt.hpp"
#include "anchorbench/work/plan.hpp"

namespace anchorbench::work {

// A chunk's attempts in unit order, each with its line of attempts.csv, so that output written
// from a chunk read back (a resumed run, an MPI rank's) has the computed chunk's bytes. Read back,
// an attempt holds what the summaries use (report::ParseAttempts).
struct ChunkResult {
  std::vector<runner::Attempt> attempts;
  std::vector<std::string> lines;
};

// Computes chunk `chunk` of `plan` on the calling thread (runner::RunRealization per unit);
// `samples` is the caller's scratch.
ChunkResult ComputeChunk(const Plan& plan, int chunk, const registry::Components& components,
                         std::vector<estimator::RangeSample>& samples);

// The chunk's text: attempts.csv's header and lines, each with compute_s as its last column.
std::string ChunkText(const ChunkResult& result);

// The file a chunk rests in (a chunk store's, a shard folder's): chunk-000012.csv.
std::string ChunkFileName(int chunk);

// A chunk's text read back; `source` names it in errors. Refuses (io::InputError) a text that is
// not every attempt of exactly the chunk's units, in order (one per anchor and trigger).
ChunkResult ParseChunk(const Plan& plan, int chunk, const std::string& text, const std::string& source);
// The same from a chunk file (a store's, a shard folder's), named in errors.
ChunkResult ReadChunkFile(const Plan& plan, int chunk, const std::string& path);

}  // namespace anchorbench::work
