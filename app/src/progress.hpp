#pragma once

#include <chrono>
#include <string>

namespace anchorbench::app {

// Progress on stderr: a live "done/total, rate, ETA" line when stderr is a terminal, otherwise one
// summary line at the end; nothing when quiet.
class Progress {
 public:
  Progress(std::string label, bool quiet);
  void Update(int done, int total);
  void Finish(int total);  // the closing line (both modes)
  double elapsed_s() const;

 private:
  std::string label_;
  bool quiet_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
};

}  // namespace anchorbench::app
