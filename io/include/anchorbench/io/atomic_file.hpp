#pragma once

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <vector>

#include "anchorbench/io/durable_file.hpp"

namespace anchorbench::io {

// One file written all or nothing (a trace beside a replay): the text goes to a temporary file
// beside the target, flushed to the disk, which Commit() renames over it. Destroyed without
// Commit() (an error, an interrupt), it removes the temporary and leaves any previous file
// untouched. The constructor refuses an existing target unless `overwrite`, and one of `inputs`
// always, removes the temporaries of killed runs, and claims `expected_bytes` on the disk (before
// the caller's work). Every error names the target, never the temporary.
class AtomicFile {
 public:
  AtomicFile(std::filesystem::path target, bool overwrite, const std::vector<std::filesystem::path>& inputs = {},
             std::uintmax_t expected_bytes = 0);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return file_.stream(); }
  void Commit();  // throws InputError (with the system's reason) if writing or the rename fails

 private:
  std::filesystem::path target_;
  DurableFile file_;
  bool committed_ = false;
};

}  // namespace anchorbench::io
