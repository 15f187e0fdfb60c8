#pragma once
// Where a run's finished chunks wait until its results are written: the folder <out>.chunks/
// beside the result folder, holding `plan.csv` naming the plan and `chunks.csv`, one file appended
// to while it is open, each chunk's text a block (block_log.hpp: a kill -9 tears at most the last).
// A run killed at any moment continues from it with --resume; the finished results replace it. The
// store is a cache of deterministic work: a chunk that does not read back as its chunk of this plan
// (torn, edited, another run's) is computed again, never trusted.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "anchorbench/io/reservation.hpp"
#include "anchorbench/engine/chunk.hpp"
#include "anchorbench/engine/plan.hpp"
#include "anchorbench/engine/block_log.hpp"

namespace anchorbench::engine {

class ChunkStore {
 public:
  enum class Mode { kFresh, kResume, kOverwrite };
  // The store for the results in `out`, before any work. kFresh refuses an existing store (an
  // interrupted run: --resume or --overwrite); kResume takes its chunks if it is `plan`'s and
  // refuses another plan's; kOverwrite discards what is there. A store folder that holds one of
  // `inputs` is refused in every mode. `expected_bytes` (the chunks still to come) are reserved
  // on the disk now and given back as chunks are saved. Errors are schema::InputError naming the
  // folder and the way out.
  ChunkStore(const std::filesystem::path& out, const Plan& plan, Mode mode, std::uintmax_t expected_bytes = 0,
             const std::vector<std::filesystem::path>& inputs = {});

  // The chunks finished before (kResume), read back and checked, by index.
  std::map<int, ChunkResult> TakeFinished();
  // Chunks found but not readable as their chunk: torn, edited, of another run (they are left
  // out of TakeFinished and computed again); the first one's reason.
  int unreadable() const { return unreadable_; }
  const std::string& first_unreadable() const { return first_unreadable_; }
  // Appends the chunk's text (one caller at a time); throws schema::InputError naming the file (a
  // full disk).
  void Save(int chunk, const std::string& text);
  // Once the results are in place.
  void Remove();

  const std::filesystem::path& folder() const { return folder_; }

 private:
  // This run's earlier store: its chunks read back (and the file rewritten with them alone when
  // it holds anything else); returns their bytes.
  std::uintmax_t TakeOver(const Plan& plan);

  std::filesystem::path folder_;
  BlockLog log_;
  std::map<int, ChunkResult> finished_;
  int unreadable_ = 0;
  std::string first_unreadable_;
  io::Reservation reservation_;
};

// <out>.chunks (a trailing separator of `out` ignored).
std::filesystem::path ChunkStorePath(const std::filesystem::path& out);

}  // namespace anchorbench::engine
