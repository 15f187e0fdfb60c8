#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "anchorbench/io/reservation.hpp"

namespace anchorbench::io {

// A result folder that appears whole or not at all. The constructor, before any long work:
// refuses a target that holds files unless `overwrite`, that holds one of `inputs` (even with
// overwrite: the swap would delete it), or that lies inside one of `input_folders`; removes what
// killed runs left behind; creates a fresh sibling, <parent>/.<name>.partial-<pid>; and reserves `expected_bytes` in it, so a read-only or
// full disk is an error now, not after hours of Monte Carlo. Write() puts each file into the
// sibling and flushes it to the disk. Commit() swaps the sibling in for the target in one atomic
// exchange (two renames where the file system has no exchange) and removes the old one.
// Destroyed without Commit() (an error, Ctrl-C), the sibling goes and the target is untouched;
// killed, the sibling stays, hidden, until the next run into the same target removes it.
class ResultFolder {
 public:
  struct Options {
    bool overwrite = false;
    std::uintmax_t expected_bytes = 0;
    std::vector<std::filesystem::path> inputs;         // files the run reads
    std::vector<std::filesystem::path> input_folders;  // folders the run reads (merge's shards)
    std::string overwrite_option = "--overwrite";      // how the caller's front spells it (Python: overwrite=True)
  };

  ResultFolder(std::filesystem::path target, const Options& options);
  ~ResultFolder();
  ResultFolder(const ResultFolder&) = delete;
  ResultFolder& operator=(const ResultFolder&) = delete;

  // Writes `name` in the folder through `write`; throws InputError (with the system's reason).
  void Write(const std::string& name, const std::function<void(std::ostream&)>& write);
  void Write(const std::string& name, const std::string& text);
  // Where files go before Commit (for writers that need a path).
  const std::filesystem::path& partial() const { return partial_; }
  void Commit();
  const std::filesystem::path& target() const { return target_; }

 private:
  std::filesystem::path target_;
  std::filesystem::path partial_;
  Reservation reservation_;
  bool committed_ = false;
};

// The folder a Monte Carlo command writes: --out if given, else results/<config name>/.
std::filesystem::path ResultFolderPath(const std::string& out, const std::string& config_name);

// Refuses (InputError) an output file that would replace one of `inputs`.
void RefuseToReplaceInputs(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs);

// Whether `path` is `folder` or lies inside it (both resolved: links, "..", relative paths).
bool IsInside(const std::filesystem::path& path, const std::filesystem::path& folder);

}  // namespace anchorbench::io
