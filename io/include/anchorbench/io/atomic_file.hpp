#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace anchorbench::io {

// Writes a file all or nothing: the text goes to a temporary file beside the target, which
// Commit() renames over it. Destroyed without Commit() (an error, an interrupt), it removes the
// temporary and leaves any previous file untouched, so no reader ever sees half a table.
class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return out_; }
  void Commit();  // throws InputError if the write or the rename fails

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  std::ofstream out_;
  bool committed_ = false;
};

// Convenience: the whole text at once.
void WriteFileAtomically(const std::filesystem::path& target, const std::string& text);

}  // namespace anchorbench::io
