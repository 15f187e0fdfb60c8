#include "anchorbench/io/result_folder.hpp"

#include <fcntl.h>  // AT_FDCWD
#include <stdio.h>  // renameat2, RENAME_EXCHANGE
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <string_view>

#include "anchorbench/io/durable_file.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::io {
namespace fs = std::filesystem;
namespace {

constexpr const char* kReservation = ".reserved";

// Joined with append: GCC 12 warns falsely (-Wrestrict) on chains of operator+ with a literal first.
std::string Join(std::initializer_list<std::string_view> parts) {
  std::string text;
  for (std::string_view part : parts) text.append(part);
  return text;
}

fs::path Parent(const fs::path& target) { return target.has_parent_path() ? target.parent_path() : fs::path("."); }

// <parent>/.<name>.<kind>-<pid>: hidden beside the target, named after the process that owns it.
fs::path Sibling(const fs::path& target, const std::string& kind, long pid) {
  return Parent(target) / Join({".", target.filename().string(), ".", kind, "-", std::to_string(pid)});
}

// What killed runs into the same target left behind: their partial and old folders.
void RemoveLeftovers(const fs::path& target) {
  const std::string prefix = Join({".", target.filename().string(), "."});
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(Parent(target), error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string rest = name.substr(prefix.size());
    const std::size_t dash = rest.rfind('-');
    if (dash == std::string::npos || (rest.substr(0, dash) != "partial" && rest.substr(0, dash) != "old")) continue;
    char* end = nullptr;
    const long pid = std::strtol(rest.c_str() + dash + 1, &end, 10);
    if (*end == '\0' && ProcessIsGone(pid)) fs::remove_all(entry.path(), error);
  }
}

bool HoldsFiles(const fs::path& folder) {
  std::error_code error;
  return fs::is_directory(folder, error) && !fs::is_empty(folder, error);
}

}  // namespace

bool IsInside(const fs::path& path, const fs::path& folder) {
  std::error_code error;
  const fs::path f = fs::weakly_canonical(path, error);
  const fs::path d = fs::weakly_canonical(folder, error);
  for (fs::path p = f; p.has_relative_path() && p != p.parent_path(); p = p.parent_path()) {
    if (p == d) return true;
  }
  return false;
}

ResultFolder::ResultFolder(fs::path target, const Options& options) : target_(std::move(target)) {
  if (target_.filename().empty()) target_ = target_.parent_path();  // "out/" names the folder "out"
  const std::string name = target_.string();
  for (const fs::path& input : options.inputs) {
    if (IsInside(input, target_)) {
      throw schema::InputError(name + ": holds " + input.string() + ", an input of this run; choose another output folder");
    }
  }
  for (const fs::path& input : options.input_folders) {
    if (IsInside(target_, input)) {
      throw schema::InputError(name + ": lies inside " + input.string() + ", an input of this run; choose another output folder");
    }
  }
  std::error_code error;
  if (fs::exists(target_, error) && !fs::is_directory(target_, error)) throw schema::InputError(name + ": exists and is not a folder");
  if (HoldsFiles(target_) && !options.overwrite) {
    throw schema::InputError(name + ": holds earlier results; add " + options.overwrite_option +
                             " to replace them (the folder is replaced as a whole once the new results are complete)");
  }
  fs::create_directories(Parent(target_), error);
  if (error) throw schema::InputError(Parent(target_).string() + ": cannot create the folder: " + error.message());
  RemoveLeftovers(target_);
  partial_ = Sibling(target_, "partial", static_cast<long>(::getpid()));
  fs::remove_all(partial_, error);
  if (!fs::create_directory(partial_, error) || error) {
    throw schema::InputError(name + ": cannot write beside it (" + partial_.string() + "): " + error.message());
  }
  try {
    reservation_ = Reservation(partial_ / kReservation, options.expected_bytes, name, "its results");
  } catch (const schema::InputError&) {
    fs::remove_all(partial_, error);
    throw;
  }
}

ResultFolder::~ResultFolder() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove_all(partial_, ignored);
}

void ResultFolder::Write(const std::string& name, const std::function<void(std::ostream&)>& write) {
  reservation_.Release();
  DurableFile file(partial_ / name);
  write(file.stream());
  file.Close();
}

void ResultFolder::Write(const std::string& name, const std::string& text) {
  Write(name, [&](std::ostream& out) { out << text; });
}

void ResultFolder::Commit() {
  reservation_.Release();
  SyncFolder(partial_);
  std::error_code error;
  if (!fs::exists(target_, error)) {
    fs::rename(partial_, target_, error);
  } else if (::renameat2(AT_FDCWD, partial_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) == 0) {
    fs::remove_all(partial_, error);  // it holds the old results now
    error.clear();
  } else {  // no atomic exchange here: two renames, the old folder set aside first
    const fs::path old = Sibling(target_, "old", static_cast<long>(::getpid()));
    fs::rename(target_, old, error);
    if (!error) fs::rename(partial_, target_, error);
    if (!error) fs::remove_all(old, error);
  }
  if (error) throw schema::InputError(target_.string() + ": cannot put the new results in place: " + error.message());
  SyncFolder(Parent(target_));
  committed_ = true;
}

fs::path ResultFolderPath(const std::string& out, const std::string& config_name) {
  return out.empty() ? fs::path("results") / config_name : fs::path(out);
}

void RefuseToReplaceInputs(const fs::path& output, const std::vector<fs::path>& inputs) {
  std::error_code error;
  for (const fs::path& input : inputs) {
    if (fs::exists(output, error) && fs::equivalent(output, input, error)) {
      throw schema::InputError(output.string() + ": is an input of this run; choose another output file");
    }
  }
}

}  // namespace anchorbench::io
