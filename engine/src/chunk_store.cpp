#include "anchorbench/engine/chunk_store.hpp"

#include <fstream>
#include <functional>
#include <system_error>

#include "anchorbench/io/atomic_file.hpp"
#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/io/result_folder.hpp"
#include "store_folder.hpp"

namespace anchorbench::engine {
namespace fs = std::filesystem;
using schema::InputError;

namespace {

constexpr const char* kPlanFile = "plan.csv";
constexpr const char* kReservation = ".reserved";

std::string IdentityIn(const fs::path& folder) {
  const fs::path path = folder / kPlanFile;
  std::ifstream in = io::OpenForReading(path.string());
  io::CsvReader csv(in, path.string());
  if (!csv.Next()) csv.Fail("no plan line");
  return std::string(csv.Text(csv.Column({"identity"})));
}

// Whether `folder` holds only what a store writes (its plan, its own files, the reservation): a
// store killed before its plan file was in place. Anything else under the store's name is a
// user's, never removed.
bool HoldsOnlyStoreFiles(const fs::path& folder, const std::function<bool(const std::string&)>& ours) {
  std::error_code error;
  if (!fs::is_directory(fs::symlink_status(folder, error))) return false;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    // The plan file's temporary is io::AtomicFile's <name>.tmp.<pid>.
    const bool store = name == kPlanFile || name == kReservation || name.rfind(std::string(kPlanFile) + ".tmp.", 0) == 0 ||
                       ours(name);
    if (!store || !entry.is_regular_file(error)) return false;
  }
  return !error;
}

constexpr const char* kChunksFile = "chunks.csv";
constexpr const char* kKind = "chunk";

// The store's file, or the temporary of its rewrite (io::AtomicFile's <name>.tmp.<pid>).
bool IsChunksFile(const std::string& name) {
  return name == kChunksFile || name.rfind(std::string(kChunksFile) + ".tmp.", 0) == 0;
}

}  // namespace

fs::path ChunkStorePath(const fs::path& out) {
  fs::path base = out;
  if (!base.has_filename()) base = base.parent_path();
  return base.parent_path() / (base.filename().string() + ".chunks");
}

bool ClaimStoreFolder(const fs::path& folder, const std::string& identity, ChunkStore::Mode mode,
                      const std::vector<fs::path>& inputs, const std::function<bool(const std::string&)>& ours,
                      const std::function<std::string()>& held) {
  for (const fs::path& input : inputs) {
    if (io::IsInside(input, folder)) {
      throw InputError(folder.string() + ": holds " + input.string() + ", an input of this run; choose another "
                                         "output folder");
    }
  }
  std::error_code error;
  if (fs::exists(fs::symlink_status(folder, error))) {
    const bool has_plan = fs::is_directory(fs::symlink_status(folder, error)) &&
                          fs::is_regular_file(folder / kPlanFile, error);
    if (!has_plan && !HoldsOnlyStoreFiles(folder, ours)) {
      throw InputError(folder.string() + ": is where this run keeps its finished chunks, and holds something else; "
                                         "move it or choose another output folder");
    }
    // Killed before its plan file was in place, a store holds nothing to keep.
    if (mode == ChunkStore::Mode::kOverwrite || !has_plan) fs::remove_all(folder, error);
  }
  if (!fs::exists(folder, error)) {
    fs::create_directories(folder, error);
    if (error) throw InputError(folder.string() + ": cannot create: " + error.message());
    return true;
  }
  if (mode == ChunkStore::Mode::kFresh) {
    throw InputError(folder.string() + ": holds " + held() +
                     " of an interrupted run: --resume continues it, --overwrite discards it");
  }
  const std::string stored = IdentityIn(folder);
  if (stored != identity) {
    throw InputError(folder.string() + ": holds chunks of another run (plan " + stored + ", this run's " + identity +
                     "): --overwrite discards them");
  }
  return false;
}

void WriteStorePlan(const fs::path& folder, const std::string& identity, long long chunks, long long units) {
  io::AtomicFile file(folder / kPlanFile, false);
  file.stream() << "identity,chunks,units\n" << identity << ',' << chunks << ',' << units << '\n';
  file.Commit();
}

ChunkStore::ChunkStore(const fs::path& out, const Plan& plan, Mode mode, std::uintmax_t expected_bytes,
                       const std::vector<fs::path>& inputs)
    : folder_(ChunkStorePath(out)) {
  const fs::path path = folder_ / kChunksFile;
  const bool fresh = ClaimStoreFolder(folder_, plan.identity(), mode, inputs, IsChunksFile, [&path] {
    long long chunks = 0;
    try {
      ReadBlockLog(path, kKind, [&chunks](LoggedBlock&&) { ++chunks; });
    } catch (const InputError&) {
      return std::string("finished chunks");
    }
    return std::to_string(chunks) + " finished chunks";
  });
  try {
    const std::uintmax_t held = fresh ? 0 : TakeOver(plan);
    reservation_ = io::Reservation(folder_ / kReservation, expected_bytes > held ? expected_bytes - held : 0,
                                   folder_.string(), "the chunks of this run");
    if (fresh) WriteStorePlan(folder_, plan.identity(), static_cast<long long>(plan.chunks().size()), plan.units());
    log_ = BlockLog(path, kKind);
  } catch (const InputError&) {
    std::error_code error;
    if (fresh) fs::remove_all(folder_, error);
    throw;
  }
}

std::uintmax_t ChunkStore::TakeOver(const Plan& plan) {
  const fs::path path = folder_ / kChunksFile;
  const auto refuse = [this](const std::string& why) {
    if (unreadable_++ == 0) first_unreadable_ = why;
  };
  std::vector<bool> kept;  // by the block's ordinal in the file
  std::uintmax_t held = 0;
  const std::string damage = ReadBlockLog(path, kKind, [&](LoggedBlock&& block) {
    const std::string source = path.string() + ":" + std::to_string(block.line);
    kept.push_back(false);
    if (block.key >= static_cast<long long>(plan.chunks().size()) || finished_.count(static_cast<int>(block.key)) > 0) {
      refuse(source + ": chunk " + std::to_string(block.key) + " is not a chunk of this plan, or a second copy");
      return;
    }
    try {
      finished_.emplace(static_cast<int>(block.key), ParseChunk(plan, static_cast<int>(block.key), block.text, source));
      held += block.text.size();
      kept.back() = true;
    } catch (const InputError& e) {
      // Torn by a crash of the machine (the file is not flushed), edited, another run's: computed again.
      refuse(e.what());
    }
  });
  if (!damage.empty()) refuse(damage);  // it comes last in the file
  // What follows a torn block would be read as part of it, and a refused block would be refused
  // again: the file keeps the chunks that read back, then grows. A store that reads back whole is
  // appended to as it is.
  if (unreadable_ > 0) RewriteBlockLog(path, kKind, [&kept](std::size_t ordinal) { return kept[ordinal]; });
  return held;
}

std::map<int, ChunkResult> ChunkStore::TakeFinished() { return std::move(finished_); }

void ChunkStore::Save(int chunk, const std::string& text) {
  reservation_.Shrink(text.size());
  log_.Append(chunk, "", text);
}

void ChunkStore::Remove() {
  log_.Close();
  std::error_code error;
  fs::remove_all(folder_, error);  // the results are in place; a leftover is refused next time
}

}  // namespace anchorbench::engine
