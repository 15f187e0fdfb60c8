#include "interrupt.hpp"

#include <csignal>

namespace anchorbench::app {
namespace {

static_assert(engine::StopFlag::is_always_lock_free, "a signal handler may only touch a lock-free atomic");

engine::StopFlag flag{false};

extern "C" void OnInterrupt(int signal) {
  flag.store(true, std::memory_order_relaxed);
  std::signal(signal, SIG_DFL);  // the next one ends the process at once
}

}  // namespace

engine::StopFlag& InterruptFlag() { return flag; }

void InstallInterruptHandlers() {
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, OnInterrupt);
}

}  // namespace anchorbench::app
