#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace anchorbench::io {

// Disk space claimed before long work, so that a full or read-only disk is an error now, not
// hours later: a file of `bytes` allocated blocks (posix_fallocate) that gives its space back as
// the real files are written (Shrink) or at once (Release). Destroyed, the file goes.
class Reservation {
 public:
  Reservation() = default;
  // Throws InputError "<what>: <kind> need about N kB: <the system's reason>".
  Reservation(std::filesystem::path file, std::uintmax_t bytes, const std::string& what, const std::string& kind);
  ~Reservation();
  Reservation(Reservation&& other) noexcept;
  Reservation& operator=(Reservation&& other) noexcept;
  Reservation(const Reservation&) = delete;
  Reservation& operator=(const Reservation&) = delete;

  void Shrink(std::uintmax_t bytes);  // gives `bytes` back (to be written now); never fails
  void Release();

 private:
  std::filesystem::path file_;
  std::uintmax_t bytes_ = 0;
};

// "12 kB", "3 MB": sizes in messages.
std::string SizeText(std::uintmax_t bytes);

}  // namespace anchorbench::io
