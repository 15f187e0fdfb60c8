#pragma once
// Ctrl-C (SIGINT), SIGTERM and SIGHUP end a command the way an error does: the flag they set stops
// the engine before its next unit (engine::Interrupted), the stack unwinds, and the partial result
// folder goes with it; finished chunks stay for --resume. A second signal ends the process at once.

#include "anchorbench/engine/run_control.hpp"

namespace anchorbench::app {

// The process's flag (a signal's is the process's by nature), set by the handlers.
engine::StopFlag& InterruptFlag();
void InstallInterruptHandlers();

}  // namespace anchorbench::app
