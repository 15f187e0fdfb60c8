#include "progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace anchorbench::app {

Progress::Progress(std::string label, bool quiet)
    : label_(std::move(label)), quiet_(quiet), terminal_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()), last_print_(start_) {}

double Progress::elapsed_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::Update(int done, int total) {
  if (quiet_ || !terminal_) return;
  const auto now = std::chrono::steady_clock::now();
  if (done < total && now - last_print_ < std::chrono::milliseconds(200)) return;
  last_print_ = now;
  const double elapsed = elapsed_s();
  const double rate = elapsed > 0.0 ? done / elapsed : 0.0;
  const double eta = rate > 0.0 ? (total - done) / rate : 0.0;
  std::fprintf(stderr, "\r%s: %d/%d realizations, %.1f/s, ETA %.0f s   ", label_.c_str(), done, total, rate, eta);
  std::fflush(stderr);
}

void Progress::Finish(int total) {
  if (quiet_) return;
  if (terminal_) std::fprintf(stderr, "\n");
  std::fprintf(stderr, "%s: %d realizations in %.2f s\n", label_.c_str(), total, elapsed_s());
}

}  // namespace anchorbench::app
