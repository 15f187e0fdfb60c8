#include "progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace anchorbench::app {

Progress::Progress(std::string label, bool quiet, std::string unit, double per_unit)
    : label_(std::move(label)), unit_(std::move(unit)), scale_(per_unit), quiet_(quiet), terminal_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()), last_print_(start_) {}

double Progress::elapsed_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::Update(long long done, long long total) {
  if (quiet_ || !terminal_) return;
  const auto now = std::chrono::steady_clock::now();
  if (done < total && now - last_print_ < std::chrono::milliseconds(200)) return;
  last_print_ = now;
  const double elapsed = elapsed_s();
  const double shown_done = done / scale_, shown_total = total / scale_;
  const double rate = elapsed > 0.0 ? shown_done / elapsed : 0.0;
  const double eta = rate > 0.0 ? (shown_total - shown_done) / rate : 0.0;
  std::fprintf(stderr, "\r%s: %.0f/%.0f %s, %.1f/s, ETA %.0f s   ", label_.c_str(), shown_done, shown_total,
               unit_.c_str(), rate, eta);
  std::fflush(stderr);
}

void Progress::Finish(long long total) {
  if (quiet_) return;
  if (terminal_) std::fprintf(stderr, "\n");
  std::fprintf(stderr, "%s: %.0f %s in %.2f s\n", label_.c_str(), total / scale_, unit_.c_str(), elapsed_s());
}

}  // namespace anchorbench::app
