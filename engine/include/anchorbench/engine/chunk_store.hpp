#pragma once
// Where a run's finished chunks wait until its results are written: the folder <out>.chunks/
// beside the result folder, one file per chunk (renamed into place whole, so a kill -9 leaves only
// whole chunks) and `plan.csv` naming the plan. A run killed at any moment continues from it with
// --resume; the finished results replace it. The store is a cache of deterministic work: a chunk
// that does not read back (a crash of the machine) is computed again, never trusted.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "anchorbench/io/reservation.hpp"
#include "anchorbench/engine/chunk.hpp"
#include "anchorbench/engine/plan.hpp"

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
  // Chunk files found but not readable as their chunk: torn, edited, of another run (they are
  // left out of TakeFinished and computed again); the first one's reason.
  int unreadable() const { return unreadable_; }
  const std::string& first_unreadable() const { return first_unreadable_; }
  // Writes the chunk's file; throws schema::InputError naming it (a full disk, a folder in its place).
  void Save(int chunk, const std::string& text);
  // Once the results are in place.
  void Remove();

  const std::filesystem::path& folder() const { return folder_; }

 private:
  std::filesystem::path ChunkPath(int chunk) const;
  void TakeOver(const Plan& plan);  // this run's earlier store: its chunks read

  std::filesystem::path folder_;
  std::map<int, ChunkResult> finished_;
  int unreadable_ = 0;
  std::string first_unreadable_;
  io::Reservation reservation_;
};

// <out>.chunks (a trailing separator of `out` ignored).
std::filesystem::path ChunkStorePath(const std::filesystem::path& out);

}  // namespace anchorbench::engine
