#include "anchorbench/engine/chunk_store.hpp"

#include <cerrno>
#include <cstring>
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

// A chunk file (chunk-N.csv) or the temporary a kill left (chunk-N.csv.partial).
bool IsChunkFile(const std::string& name) {
  return name.rfind("chunk-", 0) == 0 && (name.ends_with(".csv") || name.ends_with(".csv.partial"));
}

// Whole chunk files, not the temporaries.
int CountChunkFiles(const fs::path& folder) {
  int count = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (IsChunkFile(name) && name.ends_with(".csv")) ++count;
  }
  return count;
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
  const bool fresh = ClaimStoreFolder(folder_, plan.identity(), mode, inputs, IsChunkFile, [this] {
    return std::to_string(CountChunkFiles(folder_)) + " finished chunks";
  });
  if (!fresh) TakeOver(plan);
  try {
    std::error_code error;
    std::uintmax_t held = 0;
    for (const auto& [chunk, result] : finished_) held += fs::file_size(ChunkPath(chunk), error);
    reservation_ = io::Reservation(folder_ / kReservation, expected_bytes > held ? expected_bytes - held : 0,
                                   folder_.string(), "the chunks of this run");
    if (fresh) WriteStorePlan(folder_, plan.identity(), static_cast<long long>(plan.chunks().size()), plan.units());
  } catch (const InputError&) {
    std::error_code error;
    if (fresh) fs::remove_all(folder_, error);
    throw;
  }
}

void ChunkStore::TakeOver(const Plan& plan) {
  std::error_code error;
  for (int chunk = 0; chunk < static_cast<int>(plan.chunks().size()); ++chunk) {
    const fs::path path = ChunkPath(chunk);
    if (!fs::exists(path, error)) continue;
    if (fs::is_directory(path, error)) {
      throw InputError(path.string() + ": is a folder where the store keeps a chunk file; remove it, or --overwrite");
    }
    try {
      finished_.emplace(chunk, ReadChunkFile(plan, chunk, path.string()));
    } catch (const InputError& e) {
      // Torn by a crash of the machine (chunks are not flushed), edited, another run's: computed again.
      if (unreadable_++ == 0) first_unreadable_ = e.what();
    }
  }
}

std::map<int, ChunkResult> ChunkStore::TakeFinished() { return std::move(finished_); }

void ChunkStore::Save(int chunk, const std::string& text) {
  // Whole or absent for a killed process: the text goes to a temporary, renamed into place. Not
  // flushed to the disk (fsync made the flush, not the work, rank 0's bound): after a crash of the
  // machine a chunk may read back torn, and is then computed again.
  const fs::path path = ChunkPath(chunk);
  const fs::path temporary = path.string() + ".partial";
  reservation_.Shrink(text.size());
  std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  const int write_error = out ? 0 : errno;
  std::error_code error;
  if (!write_error) fs::rename(temporary, path, error);
  if (write_error || error) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw InputError(path.string() + ": cannot write the chunk: " +
                     (error ? error.message() : std::string(std::strerror(write_error ? write_error : EIO))));
  }
}

void ChunkStore::Remove() {
  std::error_code error;
  fs::remove_all(folder_, error);  // the results are in place; a leftover is refused next time
}

fs::path ChunkStore::ChunkPath(int chunk) const {
  return folder_ / ChunkFileName(chunk);
}

}  // namespace anchorbench::engine
