#pragma once
// The subcommands as plain functions on their arguments; main.cpp maps the command line onto them
// (and is the only file that sees CLI11). Each returns the process exit code; bad input throws
// schema::InputError, which main() reports (exit 2).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "anchorbench/io/log_policy.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/engine/executor.hpp"
#include "anchorbench/engine/run_control.hpp"

namespace anchorbench::app {

// What every command gets from the executable: the parts it offers by name, its revision, and who
// computes Monte Carlo chunks (this process's threads, or the ranks of an MPI job).
struct AppContext {
  const registry::Components& components;
  std::string revision;
  engine::Executor& executor;
  const engine::StopFlag* stop = nullptr;  // set by Ctrl-C (interrupt.hpp): the engine stops before its next unit
};

struct SimulateArgs {
  std::string config;
  std::string out;
  bool overwrite = false;
  std::optional<std::uint64_t> seed;
  std::uint64_t realization = 0;
  std::vector<std::string> overrides;  // --set KEY=VALUE
};
int SimulateCommand(const SimulateArgs& args, const AppContext& app);

struct ReplayArgs {
  std::string poses, anchors, config, trace, certificate_trace, out;
  std::vector<std::string> ranges;  // one or more files, merged by time
  io::LogPolicy policy;              // its enums set from the two names below
  std::string repeated_poses = "error", out_of_order = "sort";
  bool overwrite = false;
  bool quiet = false;
  bool navigate = false;  // the navigation filter on the log too (studies/navigation_log.hpp)
};
int ReplayCommand(const ReplayArgs& args, const AppContext& app);

// The options every Monte Carlo command shares.
struct MonteCarloArgs {
  std::string config;
  std::string out;
  int threads = 0;  // 0: OMP_NUM_THREADS, else every core
  std::optional<int> realizations;
  bool quiet = false;
  bool overwrite = false;  // replace a folder holding earlier results
  bool resume = false;     // continue from <out>.chunks/ (engine/chunk_store.hpp, record_journal.hpp)
  std::string shard;       // "I/N", this share of the chunks (or units) into a shard folder
};

struct RunArgs : MonteCarloArgs {
  std::optional<std::uint64_t> seed;
  std::vector<std::string> overrides;  // --set KEY=VALUE
};
int RunCommand(const RunArgs& args, const AppContext& app);

struct SweepArgs : MonteCarloArgs {
  std::vector<std::string> axes;  // --set KEY=VALUES (a list "a,b,c" or a range "start:stop:step")
};
int SweepCommand(const SweepArgs& args, const AppContext& app);


// A study of record units (studies/record_study.hpp), named by its command: navigate (each
// trigger's anchors in a drifting robot's filter, docs/navigation.md), explore (the closed loop,
// docs/guidance.md), pdop-study (the PDOPs side by side, docs/pdop_studies.md).
struct RecordStudyArgs : MonteCarloArgs {
  std::vector<std::string> overrides;  // --set KEY=VALUE
};
int RecordStudyCommand(const std::string& command, const RecordStudyArgs& args, const AppContext& app);

// pdop-study's own flags: --every N is --set pdop_study.every=N, --bin-s S --set pdop_study.bin_s=S
// (after the --set's, so the flags win).
struct PdopStudyArgs : RecordStudyArgs {
  std::optional<int> every;
  std::optional<double> bin_s;
  RecordStudyArgs WithSettings() const;
};

// Joins the shard folders of one run, sweep or study of record units (--shard I/N, every I) into
// its single folder.
struct MergeArgs {
  std::string out;
  std::vector<std::string> shards;
  bool overwrite = false;
  bool quiet = false;
};
int MergeCommand(const MergeArgs& args, const AppContext& app);

// `config` is a calibration file (configs/calibrate_*.yaml); --realizations is not offered (the
// file sets the fit's size, the experiment the verification's).
struct CalibrateArgs : MonteCarloArgs {
  std::string reuse;  // a finished calibration's evaluations.csv to take evaluations from
};
int CalibrateCommand(const CalibrateArgs& args, const AppContext& app);

struct ConvertHanyangArgs {
  std::string case_folder;
  std::string out;
  bool overwrite = false;
};
int ConvertHanyangCommand(const ConvertHanyangArgs& args);

// Every registered part with a one-line description.
int ListCommand(const AppContext& app);

}  // namespace anchorbench::app
