#include "anchorbench/engine/chunk_store.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

#include "anchorbench/io/atomic_file.hpp"
#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/io/result_folder.hpp"

namespace anchorbench::engine {
namespace fs = std::filesystem;
using schema::InputError;

namespace {

constexpr const char* kPlanFile = "plan.csv";
constexpr const char* kReservation = ".reserved";

void WritePlanFile(const fs::path& folder, const Plan& plan) {
  io::AtomicFile file(folder / kPlanFile, false);
  file.stream() << "identity,chunks,units\n" << plan.identity() << ',' << plan.chunks().size() << ','
                << plan.units() << '\n';
  file.Commit();
}

std::string IdentityIn(const fs::path& folder) {
  const fs::path path = folder / kPlanFile;
  std::ifstream in = io::OpenForReading(path.string());
  io::CsvReader csv(in, path.string());
  if (!csv.Next()) csv.Fail("no plan line");
  return std::string(csv.Text(csv.Column({"identity"})));
}

// Whole chunk files (chunk-N.csv), not the temporaries a kill left (chunk-N.csv.partial).
int CountChunkFiles(const fs::path& folder) {
  int count = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("chunk-", 0) == 0 && entry.path().extension() == ".csv") ++count;
  }
  return count;
}

// Whether `folder` holds only what a store writes (its plan, chunk files and their temporaries,
// the reservation): a store killed before its plan file was in place. Anything else under the
// store's name is a user's, never removed.
bool HoldsOnlyStoreFiles(const fs::path& folder) {
  std::error_code error;
  if (!fs::is_directory(fs::symlink_status(folder, error))) return false;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    // The plan file's temporary is io::AtomicFile's <name>.tmp.<pid>.
    const bool ours = name == kPlanFile || name == kReservation || name.rfind(std::string(kPlanFile) + ".tmp.", 0) == 0 ||
                      (name.rfind("chunk-", 0) == 0 && (name.ends_with(".csv") || name.ends_with(".csv.partial")));
    if (!ours || !entry.is_regular_file(error)) return false;
  }
  return !error;
}

}  // namespace

fs::path ChunkStorePath(const fs::path& out) {
  fs::path base = out;
  if (!base.has_filename()) base = base.parent_path();
  return base.parent_path() / (base.filename().string() + ".chunks");
}

ChunkStore::ChunkStore(const fs::path& out, const Plan& plan, Mode mode, std::uintmax_t expected_bytes,
                       const std::vector<fs::path>& inputs)
    : folder_(ChunkStorePath(out)) {
  for (const fs::path& input : inputs) {
    if (io::IsInside(input, folder_)) {
      throw InputError(folder_.string() + ": holds " + input.string() + ", an input of this run; choose another "
                                          "output folder");
    }
  }
  std::error_code error;
  if (fs::exists(fs::symlink_status(folder_, error))) {
    const bool has_plan = fs::is_directory(fs::symlink_status(folder_, error)) &&
                          fs::is_regular_file(folder_ / kPlanFile, error);
    if (!has_plan && !HoldsOnlyStoreFiles(folder_)) {
      throw InputError(folder_.string() + ": is where this run keeps its finished chunks, and holds something else; "
                                          "move it or choose another output folder");
    }
    // Killed before its plan file was in place, a store holds nothing to keep.
    if (mode == Mode::kOverwrite || !has_plan) fs::remove_all(folder_, error);
  }
  const bool fresh = !fs::exists(folder_, error);
  if (fresh) {
    fs::create_directories(folder_, error);
    if (error) throw InputError(folder_.string() + ": cannot create: " + error.message());
  } else {
    TakeOver(plan, mode);
  }
  try {
    std::uintmax_t held = 0;
    for (const auto& [chunk, result] : finished_) held += fs::file_size(ChunkPath(chunk), error);
    reservation_ = io::Reservation(folder_ / kReservation, expected_bytes > held ? expected_bytes - held : 0,
                                   folder_.string(), "the chunks of this run");
    if (fresh) WritePlanFile(folder_, plan);
  } catch (const InputError&) {
    if (fresh) fs::remove_all(folder_, error);
    throw;
  }
}

void ChunkStore::TakeOver(const Plan& plan, Mode mode) {
  if (mode == Mode::kFresh) {
    throw InputError(folder_.string() + ": holds " + std::to_string(CountChunkFiles(folder_)) +
                     " finished chunks of an interrupted run: --resume continues it, --overwrite discards it");
  }
  const std::string identity = IdentityIn(folder_);
  if (identity != plan.identity()) {
    throw InputError(folder_.string() + ": holds chunks of another run (plan " + identity + ", this run's " +
                     plan.identity() + "): --overwrite discards them");
  }
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
