#pragma once
// The files of a shard folder (`anchorbench run --shard I/N`) and what `anchorbench merge` reads
// back from them: attempts.csv (the shard's units in unit order, in a whole run's format),
// compute_s.csv (each attempt's compute time, for the merged timing.csv), config.yaml (the
// resolved config) and shard.csv (which share of which run, by which build).

#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "anchorbench/runner/attempt.hpp"
#include "anchorbench/runner/experiment.hpp"
#include "anchorbench/runner/shard.hpp"

namespace anchorbench::report {

struct ShardInfo {
  runner::Shard shard;
  int units = 0;            // (row, realization) units this shard holds
  std::string config_name;  // the experiment's name (its file's stem), for the merged tables
  std::string config_hash;  // io::Fingerprint of the resolved config.yaml
  std::string revision;     // of the build that ran it
};
// shard.csv: shard,of,units,config_name,config_hash,revision
void WriteShardCsv(std::ostream& out, const ShardInfo& info);
ShardInfo ReadShardCsv(const std::string& path);

// compute_s.csv: compute_s, one line per attempt of attempts.csv.
void WriteComputeCsv(std::ostream& out, const std::vector<runner::Attempt>& attempts);

// An attempts.csv read back: each attempt with what the summaries use (row, realization, method,
// initialized, t_init, error, position NEES) and its line as written, for a byte-exact merge.
struct AttemptsFile {
  std::string header;
  std::vector<runner::Attempt> attempts;
  std::vector<std::string> lines;
};
// Rows are named as in `rows`; compute_s comes from `compute_path` (same line count). Throws
// io::InputError "FILE:LINE: ..." on anything malformed.
AttemptsFile ReadAttemptsCsv(const std::string& path, const std::string& compute_path,
                             const std::vector<runner::RowConfig>& rows);

// The same from text named `source`: compute_s from `compute_in` (a compute_s.csv named
// `compute_source`), or, if null, from the text's last column (a chunk: work/chunk.hpp), which is
// then cut from the header and lines.
AttemptsFile ParseAttempts(const std::string& text, const std::string& source,
                           const std::vector<runner::RowConfig>& rows, std::istream* compute_in = nullptr,
                           const std::string& compute_source = "");

}  // namespace anchorbench::report
