#include "anchorbench/io/result_folder.hpp"

#include <fstream>

#include <gtest/gtest.h>

#include "anchorbench/io/atomic_file.hpp"
#include "anchorbench/io/durable_file.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/testing/temp_dir.hpp"

namespace anchorbench::io {
namespace {

namespace fs = std::filesystem;

std::string Read(const fs::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<std::string> Names(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

ResultFolder::Options Overwrite() {
  ResultFolder::Options options;
  options.overwrite = true;
  return options;
}

TEST(ResultFolder, AppearsOnlyAtCommitAndReplacesTheOldFolderAsAWhole) {
  testing::TempDir dir("result_folder");
  const fs::path target = dir.path() / "out";
  {
    ResultFolder folder(target, {});
    folder.Write("a.csv", "first\n");
    folder.Write("b.csv", "first\n");
    EXPECT_FALSE(fs::exists(target));  // nothing visible before the commit
    folder.Commit();
  }
  EXPECT_EQ(Names(target), (std::vector<std::string>{"a.csv", "b.csv"}));
  {
    ResultFolder folder(target, Overwrite());
    folder.Write("a.csv", "second\n");  // and no b.csv this time
    EXPECT_EQ(Read(target / "a.csv"), "first\n");
    folder.Commit();
  }
  EXPECT_EQ(Names(target), (std::vector<std::string>{"a.csv"}));  // nothing of the old folder is left
  EXPECT_EQ(Read(target / "a.csv"), "second\n");
  EXPECT_EQ(Names(dir.path()), (std::vector<std::string>{"out"}));  // no partial or old sibling
}

TEST(ResultFolder, AnErrorBeforeTheCommitLeavesTheOldResultsAndNoTrace) {
  testing::TempDir dir("result_folder_error");
  const fs::path target = dir.path() / "out";
  {
    ResultFolder folder(target, {});
    folder.Write("a.csv", "old\n");
    folder.Commit();
  }
  try {
    ResultFolder folder(target, Overwrite());
    folder.Write("a.csv", "new\n");
    throw std::runtime_error("the run failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(Read(target / "a.csv"), "old\n");
  EXPECT_EQ(Names(dir.path()), (std::vector<std::string>{"out"}));
}

TEST(ResultFolder, RefusesEarlierResultsWithoutOverwriteAndInputsAlways) {
  testing::TempDir dir("result_folder_refuse");
  const fs::path target = dir.path() / "out";
  fs::create_directories(target);
  EXPECT_NO_THROW(ResultFolder(target, {}));  // an empty folder holds nothing to lose
  dir.Write("out/poses.csv", "t,tag_id,x,y,z\n");
  EXPECT_THROW(ResultFolder(target, {}), schema::InputError);
  ResultFolder::Options options = Overwrite();
  options.inputs = {target / "poses.csv"};
  try {
    ResultFolder folder(target, options);
    FAIL() << "no error";
  } catch (const schema::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("an input of this run"), std::string::npos) << e.what();
  }
  dir.Write("file", "x");
  EXPECT_THROW(ResultFolder(dir.path() / "file", Overwrite()), schema::InputError);  // not a folder
}

TEST(ResultFolder, RemovesWhatKilledRunsLeftButNotWhatLiveOnesUse) {
  testing::TempDir dir("result_folder_stale");
  const fs::path dead = dir.path() / ".out.partial-999999999";  // no such process
  const fs::path live = dir.path() / (".out.partial-" + std::to_string(::getpid() == 1 ? 2 : 1));  // init lives
  fs::create_directories(dead);
  fs::create_directories(live);
  ResultFolder folder(dir.path() / "out", {});
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(live));
}

TEST(ResultFolder, ADiskThatCannotHoldTheResultsIsAnErrorAtTheStart) {
  testing::TempDir dir("result_folder_full");
  ResultFolder::Options options;
  options.expected_bytes = std::uintmax_t{1} << 62;  // 4 EiB: no disk has that
  try {
    ResultFolder folder(dir.path() / "out", options);
    FAIL() << "no error";
  } catch (const schema::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("its results need about"), std::string::npos) << e.what();
  }
  EXPECT_EQ(Names(dir.path()), std::vector<std::string>{});
}

// A write that fails names the file and the system's reason (here /dev/full: ENOSPC on every write).
TEST(DurableFile, AFailedWriteSaysWhy) {
  try {
    DurableFile file("/dev/full");
    file.stream() << std::string(1 << 16, 'x');
    file.Close();
    FAIL() << "no error";
  } catch (const schema::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full: writing failed: No space left on device"), std::string::npos)
        << e.what();
  }
}

TEST(AtomicFile, ReplacesOnlyWhenAskedAndNeverAnInput) {
  testing::TempDir dir("atomic_file");
  const fs::path target = dir.path() / "trace.csv";
  {
    AtomicFile file(target, false);
    file.stream() << "one\n";
    file.Commit();
  }
  EXPECT_THROW(AtomicFile(target, false), schema::InputError);
  {
    AtomicFile file(target, true);
    file.stream() << "two\n";
  }  // not committed: the old file stays, the temporary goes
  EXPECT_EQ(Read(target), "one\n");
  EXPECT_EQ(Names(dir.path()), (std::vector<std::string>{"trace.csv"}));
  EXPECT_THROW(AtomicFile(target, true, {target}), schema::InputError);
}

}  // namespace
}  // namespace anchorbench::io
