#pragma once
// A long computation from Python that Ctrl-C stops and a callback follows. The work runs on a
// thread of its own, the GIL released; the calling thread wakes every 0.1 s, reports the progress
// to `progress(done, total)` and checks for signals (Python runs its handlers on the main thread
// only). On Ctrl-C, or an error raised by `progress`, it sets the stop flag: no new unit starts, the
// Python parts running are interrupted (KeyboardInterrupt inside them), and once the work has
// ended the Python error is raised. Nothing is written: results stay in memory until save().

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>

#include "anchorbench/engine/run_control.hpp"
#include "module_parts.hpp"

namespace anchorbench::python {

// Raises KeyboardInterrupt inside every Python part running on an engine thread (plugins.cpp);
// with the GIL held.
void InterruptRunningParts();

template <typename Result>
Result Interruptible(const std::function<Result(const engine::RunControl&)>& work, const py::object& progress) {
  engine::StopFlag stop{false};
  std::atomic<long long> done{-1}, total{0};
  engine::RunControl control;
  control.stop = &stop;
  control.progress = [&](long long d, long long t) {
    total = t;
    done = d;
  };
  std::optional<Result> result;
  std::exception_ptr error;
  std::mutex mutex;
  std::condition_variable finished_cv;
  bool finished = false;
  std::thread worker([&] {
    try {
      result.emplace(work(control));
    } catch (...) {
      error = std::current_exception();
    }
    {
      const std::lock_guard<std::mutex> lock(mutex);
      finished = true;
    }
    finished_cv.notify_all();
  });
  auto stop_and_join = [&] {
    stop = true;
    InterruptRunningParts();
    py::gil_scoped_release release;
    worker.join();
  };
  long long reported = -1;
  for (;;) {
    bool over = false;
    {
      py::gil_scoped_release release;
      std::unique_lock<std::mutex> lock(mutex);
      over = finished_cv.wait_for(lock, std::chrono::milliseconds(100), [&] { return finished; });
    }
    try {
      if (!progress.is_none() && done.load() >= 0 && done.load() != reported) {
        reported = done.load();
        progress(reported, total.load());
      }
      if (over) break;
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    } catch (...) {
      stop_and_join();
      throw;
    }
  }
  worker.join();
  if (error) std::rethrow_exception(error);
  return std::move(*result);
}

}  // namespace anchorbench::python
