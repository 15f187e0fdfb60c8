#include "anchorbench/io/durable_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/io/reservation.hpp"

namespace anchorbench::io {
namespace {

constexpr std::size_t kBufferBytes = 1 << 16;

int OpenForWriting(const std::filesystem::path& path) {
  return ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
}

}  // namespace

DurableFile::Buffer::Buffer(int fd) : fd_(fd), data_(kBufferBytes) { setp(data_.data(), data_.data() + data_.size()); }

bool DurableFile::Buffer::Drain() {
  const char* next = pbase();
  while (next < pptr()) {
    const ssize_t written = ::write(fd_, next, static_cast<std::size_t>(pptr() - next));
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      if (error_ == 0) error_ = written < 0 ? errno : EIO;
      setp(data_.data(), data_.data() + data_.size());  // dropped: the file is lost anyway
      return false;
    }
    next += written;
  }
  setp(data_.data(), data_.data() + data_.size());
  return true;
}

DurableFile::Buffer::int_type DurableFile::Buffer::overflow(int_type c) {
  if (!Drain()) return traits_type::eof();
  if (!traits_type::eq_int_type(c, traits_type::eof())) sputc(traits_type::to_char_type(c));
  return traits_type::not_eof(c);
}

DurableFile::DurableFile(std::filesystem::path path, std::uintmax_t reserve_bytes, std::string shown_as)
    : path_(std::move(path)), shown_as_(shown_as.empty() ? path_.string() : std::move(shown_as)),
      fd_(OpenForWriting(path_)), buffer_(fd_), stream_(&buffer_) {
  if (fd_ < 0) Fail("cannot write", errno);
  if (reserve_bytes == 0) return;
  // Blocks claimed without growing the file; where the file system cannot, a probe of the space.
  const off_t bytes = static_cast<off_t>(reserve_bytes);
  if (::fallocate(fd_, FALLOC_FL_KEEP_SIZE, 0, bytes) == 0) return;
  const int error = errno == EOPNOTSUPP ? ::posix_fallocate(fd_, 0, bytes) : errno;
  if (::ftruncate(fd_, 0) == 0 && error == 0) return;
  ::close(fd_);  // the constructor throws: nothing of the file may stay
  fd_ = -1;
  std::error_code ignored;
  std::filesystem::remove(path_, ignored);
  Fail("needs about " + SizeText(reserve_bytes), error);
}

DurableFile::~DurableFile() {
  if (fd_ >= 0) ::close(fd_);
}

void DurableFile::Fail(const std::string& what, int error) const {
  throw schema::InputError(shown_as_ + ": " + what + (error != 0 ? std::string(": ") + std::strerror(error) : ""));
}

void DurableFile::Close() {
  const bool drained = buffer_.Drain();
  if (!drained || buffer_.error() != 0 || !stream_) Fail("writing failed", buffer_.error());
  const off_t written = ::lseek(fd_, 0, SEEK_CUR);
  if (written >= 0 && ::ftruncate(fd_, written) != 0 && errno != EINVAL) Fail("writing failed", errno);  // the reservation's rest
  if (::fsync(fd_) != 0 && errno != EINVAL) Fail("flushing to the disk failed", errno);  // EINVAL: a device file
  const int closed = ::close(fd_);
  fd_ = -1;
  if (closed != 0) Fail("writing failed", errno);
}

void SyncFolder(const std::filesystem::path& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;  // nothing to flush we could name; the rename itself has happened
  ::fsync(fd);
  ::close(fd);
}

bool ProcessIsGone(long pid) { return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH; }

}  // namespace anchorbench::io
