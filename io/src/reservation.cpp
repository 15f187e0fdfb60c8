#include "anchorbench/io/reservation.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::io {

Reservation::Reservation(std::filesystem::path file, std::uintmax_t bytes, const std::string& what,
                         const std::string& kind)
    : file_(std::move(file)), bytes_(bytes) {
  if (bytes_ == 0) {
    file_.clear();
    return;
  }
  const int fd = ::open(file_.c_str(), O_CREAT | O_WRONLY | O_TRUNC | O_CLOEXEC, 0644);
  const int reserved = fd < 0 ? errno : ::posix_fallocate(fd, 0, static_cast<off_t>(bytes_));
  if (fd >= 0) ::close(fd);
  if (reserved != 0) {
    Release();
    throw schema::InputError(what + ": " + kind + " need about " + SizeText(bytes) + ": " + std::strerror(reserved));
  }
}

Reservation::~Reservation() { Release(); }

Reservation::Reservation(Reservation&& other) noexcept
    : file_(std::exchange(other.file_, {})), bytes_(std::exchange(other.bytes_, 0)) {}

Reservation& Reservation::operator=(Reservation&& other) noexcept {
  if (this != &other) {
    Release();
    file_ = std::exchange(other.file_, {});
    bytes_ = std::exchange(other.bytes_, 0);
  }
  return *this;
}

void Reservation::Shrink(std::uintmax_t bytes) {
  if (file_.empty()) return;
  bytes_ = bytes < bytes_ ? bytes_ - bytes : 0;
  if (bytes_ == 0) return Release();
  if (::truncate(file_.c_str(), static_cast<off_t>(bytes_)) != 0) Release();  // then all of it goes back
}

void Reservation::Release() {
  if (file_.empty()) return;
  std::error_code ignored;
  std::filesystem::remove(file_, ignored);
  file_.clear();
  bytes_ = 0;
}

std::string SizeText(std::uintmax_t bytes) {
  return bytes < 1000000 ? std::to_string((bytes + 999) / 1000) + " kB" : std::to_string((bytes + 999999) / 1000000) + " MB";
}

}  // namespace anchorbench::io
