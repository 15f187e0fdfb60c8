#include "anchorbench/engine/record_journal.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/testing/temp_dir.hpp"

namespace anchorbench::engine {
namespace {

using Mode = ChunkStore::Mode;
namespace fs = std::filesystem;

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void WriteAll(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

TEST(RecordJournal, ResumesItsOwnUnitsAndRefusesAnotherJobOrAFreshStart) {
  const testing::TempDir dir("record_journal");
  const fs::path out = dir.path() / "results";
  {
    RecordJournal journal(out, "job A", 10, Mode::kFresh);
    journal.Append(3, "a,b\n");
    journal.Append(7, "c\nd\n");
  }
  EXPECT_THROW(RecordJournal(out, "job A", 10, Mode::kFresh), schema::InputError);  // an interrupted run
  EXPECT_THROW(RecordJournal(out, "job B", 10, Mode::kResume), schema::InputError);  // another job's
  RecordJournal resumed(out, "job A", 10, Mode::kResume);
  EXPECT_EQ(resumed.unreadable(), 0);
  const std::map<long long, std::string> finished = resumed.TakeFinished();
  ASSERT_EQ(finished.size(), 2u);
  EXPECT_EQ(finished.at(3), "a,b\n");
  EXPECT_EQ(finished.at(7), "c\nd\n");
  resumed.Remove();
  EXPECT_FALSE(fs::exists(dir.path() / "results.chunks"));
}

// A kill -9 while a block is written leaves it torn; an edit breaks a block's checksum. Neither is
// taken, and the units after a torn block, appended on resume, read back.
TEST(RecordJournal, ATornOrEditedUnitIsComputedAgainNeverTrusted) {
  const testing::TempDir dir("record_journal_torn");
  const fs::path out = dir.path() / "results";
  const fs::path file = dir.path() / "results.chunks" / "journal.csv";
  {
    RecordJournal journal(out, "job", 10, Mode::kFresh);
    journal.Append(1, "1.5,2\n");
    journal.Append(2, "2.5,3\n");
    journal.Append(4, "4.5,5\nsix\n");
  }
  std::string text = ReadAll(file);
  text.replace(text.find("2.5"), 3, "2.6");       // unit 2 edited
  WriteAll(file, text.substr(0, text.size() - 3));  // unit 4 torn
  {
    RecordJournal resumed(out, "job", 10, Mode::kResume);
    EXPECT_EQ(resumed.unreadable(), 2);
    EXPECT_NE(resumed.first_unreadable().find("checksum"), std::string::npos) << resumed.first_unreadable();
    const std::map<long long, std::string> finished = resumed.TakeFinished();
    ASSERT_EQ(finished.size(), 1u);
    EXPECT_EQ(finished.at(1), "1.5,2\n");
    resumed.Append(2, "2.5,3\n");
    resumed.Append(4, "4.5,5\nsix\n");
  }
  RecordJournal again(out, "job", 10, Mode::kResume);
  EXPECT_EQ(again.unreadable(), 0);
  EXPECT_EQ(again.TakeFinished().size(), 3u);
}

TEST(RecordJournal, AUnitOutsideTheJobOrTwiceIsNotTaken) {
  const testing::TempDir dir("record_journal_units");
  const fs::path out = dir.path() / "results";
  {
    RecordJournal journal(out, "job", 3, Mode::kFresh);
    journal.Append(1, "x\n");
    journal.Append(1, "y\n");
    journal.Append(5, "z\n");
  }
  RecordJournal resumed(out, "job", 3, Mode::kResume);
  EXPECT_EQ(resumed.unreadable(), 2);
  const std::map<long long, std::string> finished = resumed.TakeFinished();
  ASSERT_EQ(finished.size(), 1u);
  EXPECT_EQ(finished.at(1), "x\n");
}

TEST(RecordJournal, AFolderOfSomethingElseIsNeverRemoved) {
  const testing::TempDir dir("record_journal_other");
  const fs::path store = dir.path() / "results.chunks";
  fs::create_directories(store);
  WriteAll(store / "notes.txt", "mine");
  EXPECT_THROW(RecordJournal(dir.path() / "results", "job", 3, Mode::kOverwrite), schema::InputError);
  EXPECT_TRUE(fs::exists(store / "notes.txt"));
}

}  // namespace
}  // namespace anchorbench::engine
