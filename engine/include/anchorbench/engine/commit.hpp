#pragma once
// A run's or a sweep's result files from its attempts, written into a result folder and committed
// (run, sweep and merge write the same), and the disk space they claim before any work.

#include <cstdint>
#include <functional>
#include <ostream>
#include <optional>
#include <string>
#include <vector>

#include "anchorbench/engine/plan.hpp"
#include "anchorbench/engine/run_plan.hpp"
#include "anchorbench/engine/shard.hpp"
#include "anchorbench/io/result_folder.hpp"
#include "anchorbench/report/run_outputs.hpp"
#include "anchorbench/schema/experiment.hpp"
#include "anchorbench/schema/sweep.hpp"

namespace anchorbench::engine {

// Writes the file `name` through `write(stream)`: an io::ResultFolder's Write, or a caller that
// keeps the texts (the Python module's results, saved later with the same bytes).
using FileWriter = std::function<void(const std::string& name, const std::function<void(std::ostream&)>& write)>;

// A run's files: attempts.csv, summary.csv, summary.md, timing.csv and manifest.json, through
// `write`; returns summary.md's text.
std::string WriteRunFiles(const FileWriter& write, const schema::ExperimentConfig& config, const ExperimentAttempts& run,
                          const report::RunInfo& info);
// A sweep's files: sweep.csv, timing.csv, sweep.md and manifest.json; returns sweep.md's text.
// `plan` holds one experiment per grid point of `axes`, `points` their attempts.
std::string WriteSweepFiles(const FileWriter& write, const std::string& name, const std::vector<schema::SweepAxis>& axes,
                            const Plan& plan, const std::vector<ExperimentAttempts>& points, report::RunInfo info);

// A run's files into `out`, committed; returns summary.md's text.
std::string CommitRun(io::ResultFolder& out, const schema::ExperimentConfig& config, const ExperimentAttempts& run,
                      const report::RunInfo& info);

// A sweep's files into `out`, committed; returns sweep.md's text.
std::string CommitSweep(io::ResultFolder& out, const std::string& name, const std::vector<schema::SweepAxis>& axes,
                        const Plan& plan, const std::vector<ExperimentAttempts>& points, report::RunInfo info);

// The bytes a run claims for its results: attempts.csv (lines of 250-310 bytes) and tables; a
// shard's, its folder of chunk files.
std::uintmax_t RunResultBytes(const Plan& plan, const std::optional<Shard>& shard);
// The same for a sweep: per grid point, row and trigger a line of ~200 bytes in each of three files.
std::uintmax_t SweepResultBytes(const Plan& plan, const std::optional<Shard>& shard);

}  // namespace anchorbench::engine
