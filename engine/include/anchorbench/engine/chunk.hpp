#pragma once
// One chunk's attempts, computed or read back, and the text they travel and rest in.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "anchorbench/estimator/range_sample.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/engine/attempt.hpp"
#include "anchorbench/engine/plan.hpp"
#include "anchorbench/engine/run_control.hpp"
#include "anchorbench/engine/shard.hpp"

namespace anchorbench::engine {

// A chunk's attempts in unit order, with their lines of attempts.csv, so that output written from
// a chunk read back (a resumed run, an MPI rank's) has the computed chunk's bytes. Read back, an
// attempt holds what the summaries use (report::ParseAttempts). The lines are one text (a line an
// attempt, each ending in a newline): joined by appending, never split into strings.
struct ChunkResult {
  std::vector<schema::Attempt> attempts;
  std::string lines;
};

// Computes chunk `chunk` of `plan` on the calling thread (engine::RunRealization per unit);
// `samples` is the caller's scratch. With `stop` set, the next unit throws Interrupted.
ChunkResult ComputeChunk(const Plan& plan, int chunk, const registry::Components& components,
                         std::vector<estimator::RangeSample>& samples, const StopFlag* stop = nullptr);

// The chunk's text: an identity line, then attempts.csv's header and lines, each with compute_s as
// its last column. The identity line names the chunk, its plan and a checksum of the lines below:
//   # anchorbench chunk 12 of plan 0123456789abcdef, fnv1a64 fedcba9876543210
// The checksum (FNV-1a, 64 bits) finds edits, swapped lines, torn files and chunks of another run;
// it is no signature against someone who recomputes it.
inline constexpr std::string_view kChunkMark = "# anchorbench chunk ";
std::string ChunkText(const Plan& plan, int chunk, const ChunkResult& result);

// About the bytes of the chunk files of `shard`'s chunks (a store's or a shard folder's), for the
// space a run claims before its work: attempts.csv lines are 250-310 bytes (Table I, the halls),
// a chunk's line adds compute_s, and each file its identity and header lines.
std::uintmax_t ChunkBytes(const Plan& plan, const Shard& shard);

// The file a chunk rests in (a chunk store's, a shard folder's): chunk-000012.csv.
std::string ChunkFileName(int chunk);

// A chunk's text read back; `source` names it in errors. Refuses (schema::InputError) a text whose
// identity line is not this chunk's of this plan or whose checksum does not match, and one that is
// not every attempt of exactly the chunk's units, in order (one per anchor and trigger).
ChunkResult ParseChunk(const Plan& plan, int chunk, const std::string& text, const std::string& source);
// What an MPI worker hands rank 0 beside a chunk's text, so that rank 0 parses no text: each
// attempt's fields the summaries use (those ParseChunk reads back) as a fixed-size binary record.
// Ranks of one job run one build on one kind of machine, so the records are in its byte order.
std::string ChunkRecords(const Plan& plan, int chunk, const ChunkResult& result);
// The chunk from its text (split into attempts.csv's lines, not parsed) and its records; refuses
// (schema::InputError naming `source`) records that are not every attempt of exactly the chunk's
// units, in order, or that do not match the text's lines one for one.
ChunkResult FromRecords(const Plan& plan, int chunk, std::string_view text, std::string_view records,
                        const std::string& source);

// The same from a chunk file (a store's, a shard folder's), named in errors.
ChunkResult ReadChunkFile(const Plan& plan, int chunk, const std::string& path);

}  // namespace anchorbench::engine
