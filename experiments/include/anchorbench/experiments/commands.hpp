#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace anchorbench::experiments {

// The subcommands as plain functions on their arguments; app/main.cpp maps the command line onto
// them (and is the only file that sees CLI11). Each returns the process exit code; bad input
// throws InputError, which main() reports.

struct SimulateArgs {
  std::string config;
  std::string out;
  std::optional<std::uint64_t> seed;
  std::uint64_t realization = 0;
  std::vector<std::string> overrides;  // --set KEY=VALUE
};
int SimulateCommand(const SimulateArgs& args);

struct ReplayArgs {
  std::string poses, ranges, anchors, config, trace, out;
};
int ReplayCommand(const ReplayArgs& args);

struct RunArgs {
  std::string config;
  std::string out;
  int threads = 0;  // 0: all cores
  std::optional<std::uint64_t> seed;
  std::optional<int> realizations;
  std::vector<std::string> overrides;  // --set KEY=VALUE
  bool quiet = false;
};
int RunCommand(const RunArgs& args);

struct SweepArgs {
  std::string config;
  std::string out;
  int threads = 0;
  std::optional<int> realizations;
  std::vector<std::string> axes;  // --set KEY=VALUES (a list "a,b,c" or a range "start:stop:step")
  bool quiet = false;
};
int SweepCommand(const SweepArgs& args);

struct PdopStudyArgs {
  std::string config;
  std::string out;
  int threads = 0;
  std::optional<int> realizations;
  int every = 10;       // a checkpoint (LS and NLS solves) every this many accepted samples
  double bin_s = 10.0;  // time bins of the summary
  bool quiet = false;
};
int PdopStudyCommand(const PdopStudyArgs& args);

struct ConvertHanyangArgs {
  std::string case_folder;
  std::string out;
};
int ConvertHanyangCommand(const ConvertHanyangArgs& args);

// Every registered component with a one-line description.
int ListCommand();

}  // namespace anchorbench::experiments
