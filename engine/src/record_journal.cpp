#include "anchorbench/engine/record_journal.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <sstream>
#include <system_error>

#include "anchorbench/io/atomic_file.hpp"
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

// The numbers of a block's header line `unit,<index>,<lines>,<checksum>`; false if it is not one.
bool ParseHeader(std::string_view line, long long* unit, long long* lines, std::string* checksum) {
  if (!line.starts_with("unit,")) return false;
  line.remove_prefix(5);
  const auto number = [&line](long long* value) {
    const auto [end, ec] = std::from_chars(line.data(), line.data() + line.size(), *value);
    if (ec != std::errc() || end == line.data() + line.size() || *end != ',') return false;
    line.remove_prefix(static_cast<std::size_t>(end - line.data()) + 1);
    return true;
  };
  if (!number(unit) || !number(lines) || *lines < 1) return false;
  *checksum = std::string(line);
  return true;
}

long long CountLines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

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
      // What follows a torn block would be read as its lines: the journal is rewritten with the
      // blocks that read back, then added to.
      io::AtomicFile rewritten(path, true);
      for (const auto& [unit, text] : finished_) rewritten.stream() << Block(unit, text);
      rewritten.Commit();
    }
    file_.open(path, std::ios::binary | std::ios::app);
    if (!file_) throw InputError(path.string() + ": cannot open for appending: " + std::strerror(errno));
  } catch (const InputError&) {
    std::error_code error;
    if (fresh) fs::remove_all(folder_, error);
    throw;
  }
}

void RecordJournal::ReadBack(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  long long line_number = 0;
  const auto refuse = [this, &path](long long at, const std::string& why) {
    if (unreadable_++ == 0) first_unreadable_ = path.string() + ":" + std::to_string(at) + ": " + why;
  };
  while (std::getline(in, line)) {
    const long long header_at = ++line_number;
    long long unit = 0, lines = 0;
    std::string checksum;
    if (!ParseHeader(line, &unit, &lines, &checksum)) {
      refuse(header_at, "not a unit's header line");
      continue;
    }
    std::string text;
    long long read = 0;  // a last line without its newline is torn
    while (read < lines && std::getline(in, line) && !in.eof()) {
      text.append(line).push_back('\n');
      ++read;
    }
    line_number += read;
    const std::string what = "unit " + std::to_string(unit);
    if (read < lines) {
      refuse(header_at, what + " is torn (the run was killed while writing it)");
      break;
    }
    if (unit < 0 || unit >= units_ || finished_.count(unit) > 0) {
      refuse(header_at, what + " is not a unit of this run, or a second copy");
    } else if (checksum != Checksum(unit, text)) {
      refuse(header_at, what + " does not match its checksum (edited after the run, or another run's?)");
    } else {
      finished_.emplace(unit, std::move(text));
    }
  }
}

void RecordJournal::Refuse(long long unit, const std::string& why) {
  if (unreadable_++ == 0) first_unreadable_ = (folder_ / kJournalFile).string() + ": unit " + std::to_string(unit) + ": " + why;
}

std::string RecordJournal::Checksum(long long unit, const std::string& text) const {
  return io::Fingerprint(identity_ + "\n" + std::to_string(unit) + "\n" + text);
}

std::string RecordJournal::Block(long long unit, const std::string& text) const {
  return "unit," + std::to_string(unit) + "," + std::to_string(CountLines(text)) + "," + Checksum(unit, text) + "\n" +
         text;
}

void RecordJournal::Append(long long unit, const std::string& text) {
  const std::string block = Block(unit, text);
  const std::lock_guard<std::mutex> lock(mutex_);
  // One write of the whole block, flushed at once: a kill -9 tears at most this block.
  file_.write(block.data(), static_cast<std::streamsize>(block.size()));
  file_.flush();
  if (!file_) throw InputError((folder_ / kJournalFile).string() + ": cannot append a finished unit: " + std::strerror(errno));
}

void RecordJournal::Remove() {
  file_.close();
  std::error_code error;
  fs::remove_all(folder_, error);  // the results are in place; a leftover is refused next time
}

}  // namespace anchorbench::engine
