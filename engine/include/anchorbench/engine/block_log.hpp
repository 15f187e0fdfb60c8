#pragma once
// The one file a store appends its finished work to: blocks, each a header line
// `<kind>,<key>,<bytes>,<tag>` and then `bytes` bytes of text. The chunk store (kind `chunk`, its
// texts checked by their own identity lines) and the record journal (kind `unit`, its tag a
// checksum) both keep their work in one.
//
// A block is written whole and handed to the system at once (not flushed to the disk): a killed
// process tears at most the last block, which reads back as torn and is computed again. Appending
// to an open file costs a write; creating a file per block cost more than twice as much (bench_ingest).
// Reading streams one block at a time: a store of gigabytes is never held whole.

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <string_view>

namespace anchorbench::engine {

struct LoggedBlock {
  long long key = 0;
  std::string tag;
  std::string text;
  long long line = 0;  // of its header in the file, for messages
};

// Hands each whole block of kind `kind` in `path` to `take`, in the file's order (a missing file
// has none); returns where and why reading stopped early ("FILE:LINE: ..."), or empty when the
// file is whole blocks to its end. Reading stops at the first header that does not parse or the
// first block cut short: what follows cannot be delimited. A folder in the file's place is an
// InputError naming it.
std::string ReadBlockLog(const std::filesystem::path& path, std::string_view kind,
                         const std::function<void(LoggedBlock&& block)>& take);

// A block as the file holds it: its header line, then `text`.
std::string BlockText(std::string_view kind, long long key, std::string_view tag, std::string_view text);

// `path` rewritten (whole or absent) with the whole blocks whose ordinal in the file (0, 1, ...)
// `keep` says, and nothing after them: what a resumed store keeps before it appends more.
void RewriteBlockLog(const std::filesystem::path& path, std::string_view kind,
                     const std::function<bool(std::size_t ordinal)>& keep);

class BlockLog {
 public:
  BlockLog() = default;
  // Opens `path` for appending; throws schema::InputError naming it.
  BlockLog(const std::filesystem::path& path, std::string kind);
  // Adds a block; the caller holds it to one thread at a time. Throws schema::InputError naming the
  // file when it cannot be written (a full disk).
  void Append(long long key, std::string_view tag, std::string_view text);
  void Close() { file_.close(); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::string kind_;
  std::ofstream file_;
};

}  // namespace anchorbench::engine
