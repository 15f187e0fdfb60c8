#include "anchorbench/engine/block_log.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <system_error>

#include "anchorbench/io/atomic_file.hpp"
#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::engine {
namespace fs = std::filesystem;
using schema::InputError;

namespace {

std::string Header(std::string_view kind, long long key, std::size_t bytes, std::string_view tag) {
  std::string header(kind);
  header.append(",").append(std::to_string(key)).append(",").append(std::to_string(bytes)).append(",");
  header.append(tag).push_back('\n');
  return header;
}

// `<kind>,<key>,<bytes>,<tag>`: false if `line` is not such a header.
bool ParseHeader(std::string_view line, std::string_view kind, long long* key, long long* bytes, std::string* tag) {
  if (!line.starts_with(kind) || line.substr(kind.size(), 1) != ",") return false;
  line.remove_prefix(kind.size() + 1);
  const auto number = [&line](long long* value) {
    const auto [end, ec] = std::from_chars(line.data(), line.data() + line.size(), *value);
    if (ec != std::errc() || end == line.data() + line.size() || *end != ',' || *value < 0) return false;
    line.remove_prefix(static_cast<std::size_t>(end - line.data()) + 1);
    return true;
  };
  if (!number(key) || !number(bytes)) return false;
  *tag = std::string(line);
  return true;
}

}  // namespace

BlockLogContents ReadBlockLog(const fs::path& path, std::string_view kind) {
  BlockLogContents contents;
  std::error_code error;
  if (!fs::exists(fs::symlink_status(path, error))) return contents;
  if (!fs::is_regular_file(fs::symlink_status(path, error))) {
    throw InputError(path.string() + ": is not a file where the store keeps its finished work; remove it, or --overwrite");
  }
  const std::string text = io::ReadWholeFile(path.string());
  std::size_t at = 0;
  long long line = 1;
  while (at < text.size()) {
    const std::size_t newline = text.find('\n', at);
    LoggedBlock block;
    long long bytes = 0;
    const std::string place = path.string() + ":" + std::to_string(line);
    if (newline == std::string::npos || !ParseHeader(std::string_view(text).substr(at, newline - at), kind,
                                                     &block.key, &bytes, &block.tag)) {
      contents.damage = place + ": not a block's header line (torn, or edited)";
      break;
    }
    if (static_cast<std::size_t>(bytes) > text.size() - newline - 1) {
      contents.damage = place + ": " + std::string(kind) + " " + std::to_string(block.key) +
                        " is torn (the run was killed while writing it)";
      break;
    }
    block.text = text.substr(newline + 1, static_cast<std::size_t>(bytes));
    block.line = line;
    line += 1 + static_cast<long long>(std::count(block.text.begin(), block.text.end(), '\n'));
    at = newline + 1 + static_cast<std::size_t>(bytes);
    contents.blocks.push_back(std::move(block));
  }
  contents.clean = contents.damage.empty();
  return contents;
}

void RewriteBlockLog(const fs::path& path, std::string_view kind, const std::vector<LoggedBlock>& blocks) {
  io::AtomicFile file(path, true);
  for (const LoggedBlock& block : blocks) file.stream() << Header(kind, block.key, block.text.size(), block.tag) << block.text;
  file.Commit();
}

BlockLog::BlockLog(const fs::path& path, std::string kind) : path_(path), kind_(std::move(kind)) {
  file_.open(path, std::ios::binary | std::ios::app);
  if (!file_) throw InputError(path.string() + ": cannot open for appending: " + std::strerror(errno));
}

void BlockLog::Append(long long key, std::string_view tag, std::string_view text) {
  const std::string header = Header(kind_, key, text.size(), tag);
  file_.write(header.data(), static_cast<std::streamsize>(header.size()));
  file_.write(text.data(), static_cast<std::streamsize>(text.size()));
  file_.flush();  // to the system now: a kill -9 tears at most this block
  if (!file_) {
    const int error = errno;
    throw InputError(path_.string() + ": cannot append " + kind_ + " " + std::to_string(key) + ": " +
                     std::strerror(error ? error : EIO));
  }
}

}  // namespace anchorbench::engine
