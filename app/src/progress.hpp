#pragma once

#include <chrono>
#include <string>

namespace anchorbench::app {

// Progress on stderr: a live "done/total, rate, ETA" line when stderr is a terminal, otherwise one
// summary line at the end; nothing when quiet.
class Progress {
 public:
  // `unit` names what is shown; `per_unit` counted items make one (1e6 bytes for "MB").
  Progress(std::string label, bool quiet, std::string unit = "realizations", double per_unit = 1.0);
  void Update(long long done, long long total);
  void Finish(long long total);  // the closing line (both modes)
  double elapsed_s() const;

 private:
  std::string label_;
  std::string unit_;
  double scale_;  // counted units per shown unit
  bool quiet_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
};

}  // namespace anchorbench::app
