#pragma once

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

namespace anchorbench::io {

// A file being written that reaches the disk before Close() returns: buffered writes on a file
// descriptor of its own, then fsync and close, each checked. The first failure is kept with the
// system's reason, and Close() throws it as an InputError naming the file ("No space left on
// device", "Read-only file system", ...). `reserve_bytes` are claimed on the disk at once (a full
// disk is an error before the caller's work, not after), and what is not written is given back at
// Close(). Errors name `shown_as` (the file the user asked for, where `path` is a temporary).
class DurableFile {
 public:
  explicit DurableFile(std::filesystem::path path, std::uintmax_t reserve_bytes = 0, std::string shown_as = "");
  ~DurableFile();
  DurableFile(const DurableFile&) = delete;
  DurableFile& operator=(const DurableFile&) = delete;

  std::ostream& stream() { return stream_; }
  void Close();
  const std::filesystem::path& path() const { return path_; }

 private:
  // The buffer between the stream and write(2); remembers the errno of the first failed write.
  class Buffer : public std::streambuf {
   public:
    explicit Buffer(int fd);
    bool Drain();  // writes out what is buffered; false on failure
    int error() const { return error_; }

   protected:
    int_type overflow(int_type c) override;
    int sync() override { return Drain() ? 0 : -1; }

   private:
    int fd_;
    std::vector<char> data_;
    int error_ = 0;
  };

  [[noreturn]] void Fail(const std::string& what, int error) const;

  std::filesystem::path path_;
  std::string shown_as_;
  int fd_ = -1;
  Buffer buffer_;
  std::ostream stream_;
};

// fsync of a folder, so that the names created or renamed in it survive a power cut.
void SyncFolder(const std::filesystem::path& folder);

// Whether the process that named a temporary after its pid is gone (its leftovers may go).
bool ProcessIsGone(long pid);

}  // namespace anchorbench::io
