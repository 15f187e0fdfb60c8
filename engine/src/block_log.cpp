#include "anchorbench/engine/block_log.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <system_error>

#include "anchorbench/io/atomic_file.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::engine {
namespace fs = std::filesystem;
using schema::InputError;

namespace {

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

std::string Header(std::string_view kind, long long key, std::size_t bytes, std::string_view tag) {
  std::string header(kind);
  header.append(",").append(std::to_string(key)).append(",").append(std::to_string(bytes)).append(",");
  header.append(tag).push_back('\n');
  return header;
}

}  // namespace

std::string BlockText(std::string_view kind, long long key, std::string_view tag, std::string_view text) {
  std::string block = Header(kind, key, text.size(), tag);
  block.append(text);
  return block;
}

std::string ReadBlockLog(const fs::path& path, std::string_view kind, const std::function<void(LoggedBlock&&)>& take) {
  std::error_code error;
  if (!fs::exists(fs::symlink_status(path, error))) return "";
  if (!fs::is_regular_file(fs::symlink_status(path, error))) {
    throw InputError(path.string() + ": is not a file where the store keeps its finished work; remove it, or --overwrite");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot open the file: " + std::strerror(errno));
  std::string header;
  long long line = 1;
  while (std::getline(in, header)) {
    const std::string place = path.string() + ":" + std::to_string(line);
    LoggedBlock block;
    long long bytes = 0;
    if (in.eof() || !ParseHeader(header, kind, &block.key, &bytes, &block.tag)) {
      return place + ": not a block's header line (torn, or edited)";
    }
    block.text.resize(static_cast<std::size_t>(bytes));
    in.read(block.text.data(), static_cast<std::streamsize>(bytes));
    if (in.gcount() != static_cast<std::streamsize>(bytes)) {
      return place + ": " + std::string(kind) + " " + std::to_string(block.key) +
             " is torn (the run was killed while writing it)";
    }
    block.line = line;
    line += 1 + static_cast<long long>(std::count(block.text.begin(), block.text.end(), '\n'));
    take(std::move(block));
  }
  return "";
}

void RewriteBlockLog(const fs::path& path, std::string_view kind, const std::function<bool(std::size_t)>& keep) {
  io::AtomicFile file(path, true);
  std::size_t ordinal = 0;
  ReadBlockLog(path, kind, [&](LoggedBlock&& block) {
    if (keep(ordinal++)) file.stream() << Header(kind, block.key, block.text.size(), block.tag) << block.text;
  });
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
