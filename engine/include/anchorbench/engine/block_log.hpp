#pragma once
// The one file a store appends its finished work to: blocks, each a header line
// `<kind>,<key>,<bytes>,<tag>` and then `bytes` bytes of text. The chunk store (kind `chunk`, its
// texts checked by their own identity lines) and the record journal (kind `unit`, its tag a
// checksum) both keep their work in one.
//
// A block is written whole and handed to the system at once (not flushed to the disk): a killed
// process tears at most the last block, which reads back as torn and is computed again. Appending
// to an open file costs a write; creating a file per block cost about ten times more (bench_ingest).

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace anchorbench::engine {

struct LoggedBlock {
  long long key = 0;
  std::string tag;
  std::string text;
  long long line = 0;  // of its header in the file, for messages
};

struct BlockLogContents {
  std::vector<LoggedBlock> blocks;  // whole blocks, in the file's order (not yet checked by their store)
  std::string damage;               // empty, or where the blocks stop reading back and why ("FILE:LINE: ...")
  bool clean = true;                // false when the file holds more than `blocks` (a tear, a stray line)
};

// The blocks of kind `kind` in `path` (a missing file has none). Reading stops at the first header
// that does not parse or the first block cut short: what follows cannot be delimited.
BlockLogContents ReadBlockLog(const std::filesystem::path& path, std::string_view kind);

// `path` rewritten (whole or absent) with `blocks` alone: what a resumed store keeps, before it
// appends more.
void RewriteBlockLog(const std::filesystem::path& path, std::string_view kind, const std::vector<LoggedBlock>& blocks);

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
