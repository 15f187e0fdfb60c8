#include "anchorbench/io/atomic_file.hpp"

#include <unistd.h>

#include "anchorbench/io/input_error.hpp"

namespace anchorbench::io {

AtomicFile::AtomicFile(std::filesystem::path target)
    : target_(std::move(target)),
      temporary_(target_.string() + ".tmp." + std::to_string(::getpid())),
      out_(temporary_, std::ios::binary | std::ios::trunc) {
  if (!out_) throw InputError(target_.string() + ": cannot write (does the folder exist and is it writable?)");
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  out_.close();
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void AtomicFile::Commit() {
  out_.flush();
  const bool written = static_cast<bool>(out_);
  out_.close();
  std::error_code error;
  if (written) std::filesystem::rename(temporary_, target_, error);
  if (!written || error) throw InputError(target_.string() + ": writing failed" + (error ? ": " + error.message() : ""));
  committed_ = true;
}

void WriteFileAtomically(const std::filesystem::path& target, const std::string& text) {
  AtomicFile file(target);
  file.stream() << text;
  file.Commit();
}

}  // namespace anchorbench::io
