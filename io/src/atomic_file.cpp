#include "anchorbench/io/atomic_file.hpp"

#include <unistd.h>

#include <cstdlib>

#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/io/result_folder.hpp"

namespace anchorbench::io {
namespace fs = std::filesystem;
namespace {

// <target>.tmp.<pid>; checked for the target before the temporary is opened.
fs::path Temporary(const fs::path& target, bool overwrite, const std::vector<fs::path>& inputs) {
  RefuseToReplaceInputs(target, inputs);
  std::error_code error;
  if (fs::exists(target, error) && !overwrite) {
    throw schema::InputError(target.string() + ": exists; add --overwrite to replace it");
  }
  // The temporaries of killed runs: <target>.tmp.<pid> of processes that are gone.
  const std::string prefix = target.filename().string() + ".tmp.";
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    char* end = nullptr;
    const long pid = std::strtol(name.c_str() + prefix.size(), &end, 10);
    if (*end == '\0' && ProcessIsGone(pid)) fs::remove(entry.path(), error);
  }
  return target.string() + ".tmp." + std::to_string(::getpid());
}

}  // namespace

AtomicFile::AtomicFile(fs::path target, bool overwrite, const std::vector<fs::path>& inputs,
                       std::uintmax_t expected_bytes)
    : target_(std::move(target)), file_(Temporary(target_, overwrite, inputs), expected_bytes, target_.string()) {}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove(file_.path(), ignored);
}

void AtomicFile::Commit() {
  file_.Close();
  std::error_code error;
  fs::rename(file_.path(), target_, error);
  if (error) throw schema::InputError(target_.string() + ": cannot put the new file in place: " + error.message());
  SyncFolder(target_.has_parent_path() ? target_.parent_path() : fs::path("."));
  committed_ = true;
}

}  // namespace anchorbench::io
