#pragma once
// Where a study's finished units wait until its results are written, for studies whose units give
// records rather than attempts (navigate): <out>.chunks/ beside the result folder, claimed like the
// chunk store's (the same modes, the same refusals), holding `plan.csv` and one file,
// `journal.csv`, appended to while it is open like the chunk store's (block_log.hpp): each unit a
// block `unit,<index>,<bytes>,<checksum>` and its records' lines. A kill -9 leaves at most the last
// block torn. A block that does not read back whole or does not match its checksum (of the job's
// identity, the unit and its text: torn, edited, of another job) is computed again, never trusted;
// on resume the journal is rewritten with the blocks that read back before more are added.

#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "anchorbench/engine/block_log.hpp"
#include "anchorbench/engine/chunk_store.hpp"

namespace anchorbench::engine {

// A unit's block: its kind, and its checksum (of the job's identity, the unit and its text). A
// record study's shard file holds the same blocks (shard_folder.hpp).
inline constexpr const char* kUnitBlockKind = "unit";
// Where a unit's text was read: its file, and the line of its block's header (the text's first
// line is the next), for messages on its records.
struct UnitPlace {
  std::string file;
  long long line = 0;
  std::string where() const { return file + ":" + std::to_string(line); }  // "FILE:LINE", as messages begin
};
std::string UnitChecksum(std::string_view identity, long long unit, std::string_view text);

class RecordJournal {
 public:
  // The journal of the results in `out` for the job `identity` of `units` units, before any work
  // (ChunkStore's modes and errors).
  RecordJournal(const std::filesystem::path& out, std::string identity, long long units, ChunkStore::Mode mode,
                const std::vector<std::filesystem::path>& inputs = {});

  // The units finished before (kResume) that read back: index -> their lines.
  std::map<long long, std::string> TakeFinished() { return std::move(finished_); }
  // Blocks found but not read back; the first one's reason.
  int unreadable() const { return unreadable_; }
  const std::string& first_unreadable() const { return first_unreadable_; }
  // Adds a finished unit (`text`: whole lines); from any thread. Throws schema::InputError naming
  // the file when it cannot be written (a full disk).
  void Append(long long unit, const std::string& text);
  // Once the results are in place.
  void Remove();

  const std::filesystem::path& folder() const { return folder_; }
  // Where a unit TakeFinished gave was read.
  UnitPlace PlaceOf(long long unit) const;
  // A unit TakeFinished gave that the study's parser refuses, and why (a whole message, naming
  // its place): counted with the unreadable blocks (the caller computes it again).
  void Refuse(const std::string& why);

 private:
  void ReadBack(const std::filesystem::path& path);  // the blocks that read back, into finished_

  std::filesystem::path folder_;
  std::string identity_;
  long long units_ = 0;
  std::map<long long, std::string> finished_;
  std::map<long long, long long> lines_;  // of each finished unit's block
  int unreadable_ = 0;
  std::string first_unreadable_;
  std::mutex mutex_;
  BlockLog log_;
};

}  // namespace anchorbench::engine
