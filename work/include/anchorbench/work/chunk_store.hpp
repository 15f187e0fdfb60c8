#pragma once
// Where a run's finished chunks wait until its results are written: the folder <out>.chunks/
// beside the result folder, one file per chunk (renamed into place whole, so a kill -9 leaves only
// whole chunks) and `plan.csv` naming the plan. A run killed at any moment continues from it with
// --resume; the finished results replace it. The store is a cache of deterministic work: a chunk
// that does not read back (a crash of the machine) is computed again, never trusted.

#include <filesystem>
#include <map>
#include <string>

#include "anchorbench/work/chunk.hpp"
#include "anchorbench/work/plan.hpp"

namespace anchorbench::work {

class ChunkStore {
 public:
  enum class Mode { kFresh, kResume, kOverwrite };
  // The store for the results in `out`, before any work. kFresh refuses an existing store (an
  // interrupted run: --resume or --overwrite); kResume takes its chunks if it is `plan`'s and
  // refuses another plan's; kOverwrite discards what is there. Errors are io::InputError naming
  // the folder and the way out.
  ChunkStore(const std::filesystem::path& out, const Plan& plan, Mode mode);

  // The chunks finished before (kResume), read back and checked, by index.
  std::map<int, ChunkResult> TakeFinished();
  // Chunk files found but not readable as their chunk (they are left out of TakeFinished).
  int unreadable() const { return unreadable_; }
  void Save(int chunk, const std::string& text);
  // Once the results are in place.
  void Remove();

  const std::filesystem::path& folder() const { return folder_; }

 private:
  std::filesystem::path ChunkPath(int chunk) const;

  std::filesystem::path folder_;
  std::map<int, ChunkResult> finished_;
  int unreadable_ = 0;
};

// <out>.chunks (a trailing separator of `out` ignored).
std::filesystem::path ChunkStorePath(const std::filesystem::path& out);

}  // namespace anchorbench::work
