#pragma once
// attempts.csv read back (report::WriteAttempts' twin): what the summaries use, and each line as
// written, so that results joined from read-back attempts (a resumed run, a merge, an MPI rank's
// chunks) are byte for byte those of one process.

#include <istream>
#include <string>
#include <vector>

#include "anchorbench/schema/attempt.hpp"
#include "anchorbench/schema/experiment.hpp"

namespace anchorbench::report {

// Each attempt with what the summaries use (row, realization, method, initialized, t_init, error,
// position NEES, the oracle's time and the latency, compute_s), and their lines as written (one
// text, a line an attempt, each ending in a newline).
struct AttemptsFile {
  std::vector<schema::Attempt> attempts;
  std::string lines;
};

// attempts.csv's text, named `source` in errors, with compute_s as a last column (a chunk:
// engine/chunk.hpp), which is cut from the header and the lines. Rows are named as in `rows`.
// Throws schema::InputError "SOURCE:LINE: ..." on anything malformed.
AttemptsFile ParseAttempts(const std::string& text, const std::string& source,
                           const std::vector<schema::RowConfig>& rows);

}  // namespace anchorbench::report
