#include "anchorbench/engine/record_journal.hpp"

#include <system_error>

#include "anchorbench/io/hash.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "store_folder.hpp"

namespace anchorbench::engine {
namespace fs = std::filesystem;
using schema::InputError;

namespace {

constexpr const char* kJournalFile = "journal.csv";

// The journal, or the temporary of its rewrite (io::AtomicFile's <name>.tmp.<pid>).
bool IsJournalFile(const std::string& name) {
  return name == kJournalFile || name.rfind(std::string(kJournalFile) + ".tmp.", 0) == 0;
}

}  // namespace

RecordJournal::RecordJournal(const fs::path& out, std::string identity, long long units, ChunkStore::Mode mode,
                             const std::vector<fs::path>& inputs)
    : folder_(ChunkStorePath(out)), identity_(std::move(identity)), units_(units) {
  const fs::path path = folder_ / kJournalFile;
  const bool fresh = ClaimStoreFolder(folder_, identity_, mode, inputs, IsJournalFile, [&path] {
    std::error_code error;
    return "a journal of finished units (" + std::to_string(fs::file_size(path, error)) + " bytes)";
  });
  try {
    if (fresh) {
      WriteStorePlan(folder_, identity_, units_, units_);
    } else {
      ReadBack(path);
    }
    log_ = BlockLog(path, kUnitBlockKind);
  } catch (const InputError&) {
    std::error_code error;
    if (fresh) fs::remove_all(folder_, error);
    throw;
  }
}

void RecordJournal::ReadBack(const fs::path& path) {
  std::vector<bool> kept;  // by the block's ordinal in the file
  const std::string damage = ReadBlockLog(path, kUnitBlockKind, [&](LoggedBlock&& block) {
    const std::string what = UnitPlace{path.string(), block.line}.where() + ": unit " + std::to_string(block.key);
    std::string why;
    if (block.key >= units_ || finished_.count(block.key) > 0) {
      why = what + " is not a unit of this run, or a second copy";
    } else if (block.tag != UnitChecksum(identity_, block.key, block.text)) {
      why = what + " does not match its checksum (edited after the run, or another run's?)";
    }
    kept.push_back(why.empty());
    if (!why.empty()) {
      if (unreadable_++ == 0) first_unreadable_ = why;
      return;
    }
    lines_.emplace(block.key, block.line);
    finished_.emplace(block.key, std::move(block.text));
  });
  if (!damage.empty() && unreadable_++ == 0) first_unreadable_ = damage;  // it comes last in the file
  // What follows a torn block would be read as part of it: the journal keeps the blocks that read
  // back, then grows.
  if (unreadable_ > 0) RewriteBlockLog(path, kUnitBlockKind, [&kept](std::size_t ordinal) { return kept[ordinal]; });
}

UnitPlace RecordJournal::PlaceOf(long long unit) const {
  const auto line = lines_.find(unit);
  return {(folder_ / kJournalFile).string(), line == lines_.end() ? 0 : line->second};
}

void RecordJournal::Refuse(const std::string& why) {
  if (unreadable_++ == 0) first_unreadable_ = why;
}

std::string UnitChecksum(std::string_view identity, long long unit, std::string_view text) {
  std::string hashed(identity);
  hashed.append("\n").append(std::to_string(unit)).append("\n").append(text);
  return io::Fingerprint(hashed);
}

void RecordJournal::Append(long long unit, const std::string& text) {
  const std::string checksum = UnitChecksum(identity_, unit, text);
  const std::lock_guard<std::mutex> lock(mutex_);
  log_.Append(unit, checksum, text);
}

void RecordJournal::Remove() {
  log_.Close();
  std::error_code error;
  fs::remove_all(folder_, error);  // the results are in place; a leftover is refused next time
}

}  // namespace anchorbench::engine
