#include "anchorbench/studies/evaluation_log.hpp"

#include <filesystem>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>

#include "anchorbench/io/hash.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::studies {
namespace {

namespace fs = std::filesystem;

class EvaluationLogTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("evaluation_log_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  static EvaluationLog Log(std::uint64_t context = 7) { return EvaluationLog({"a.x", "a.y"}, {"1.fixed.avg_m", "1.gated.init"}, context); }
  static Evaluation At(const std::string& x, double avg) { return {"global", {x, "2"}, {avg, std::nullopt}, avg * avg}; }
  fs::path dir_;
};

TEST_F(EvaluationLogTest, WritesEachComputedEvaluationAndReadsItBackExactly) {
  const fs::path path = dir_ / "log.csv";
  {
    EvaluationLog log = Log();
    log.AppendTo(path);
    log.Record(At("0.5", 0.1 + 0.2), true);   // a value that needs all 17 digits
    log.Record(At("0.25", 1.0 / 3.0), false);  // known already: not written again
  }
  std::ifstream in(path);
  std::string header, line, rest;
  std::getline(in, header);
  std::getline(in, line);
  EXPECT_EQ(header, "context,evaluation,stage,a.x,a.y,objective,1.fixed.avg_m,1.gated.init,checksum");
  EXPECT_EQ(line.substr(0, 26), "0000000000000007,0,global,");
  EXPECT_FALSE(std::getline(in, rest));

  EvaluationLog again = Log();
  EXPECT_EQ(again.Reuse(path), 1);
  const auto* known = again.Find({"0.5", "2"});
  ASSERT_NE(known, nullptr);
  EXPECT_EQ(*(*known)[0], 0.1 + 0.2);  // bit for bit
  EXPECT_FALSE((*known)[1]);
  EXPECT_EQ(again.Find({"0.25", "2"}), nullptr);
}

TEST_F(EvaluationLogTest, IgnoresATornLastLineAndOtherContexts) {
  const fs::path path = dir_ / "log.csv";
  {
    EvaluationLog log = Log();
    log.AppendTo(path);
    log.Record(At("0.5", 0.3), true);
  }
  {
    EvaluationLog other = Log(8);  // another experiment or fit size
    other.AppendTo(path);
    other.Record(At("0.75", 0.4), true);
  }
  std::ofstream(path, std::ios::app) << "0000000000000007,2,global,0.9,2,0.01,0.";  // killed mid-line
  EvaluationLog log = Log();
  EXPECT_EQ(log.Reuse(path), 1);
  EXPECT_EQ(log.Find({"0.75", "2"}), nullptr);
  // Appending again cuts the torn line first, so the file stays readable.
  log.AppendTo(path);
  log.Record(At("0.1", 0.5), true);
  EvaluationLog later = Log();
  EXPECT_EQ(later.Reuse(path), 2);
}

TEST_F(EvaluationLogTest, RefusesALogOfOtherParameters) {
  const fs::path path = dir_ / "log.csv";
  std::ofstream(path) << "context,evaluation,stage,b,objective,1.fixed.avg_m\n";
  EvaluationLog log = Log();
  try {
    log.Reuse(path);
    FAIL() << "expected an error";
  } catch (const schema::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("log.csv:1: the log is of other parameters or cells"), std::string::npos);
  }
}

// Each line carries the checksum of what precedes it: an edited cell, a negative or non-finite
// one, and an evaluation repeated with other cells are refused with the line to cut.
TEST_F(EvaluationLogTest, RefusesEditedLinesAndNamesTheLineToCut) {
  const fs::path path = dir_ / "log.csv";
  {
    EvaluationLog log = Log();
    log.AppendTo(path);
    log.Record(At("0.5", 0.25), true);
    log.Record(At("0.75", 0.5), true);
  }
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 3u);
  const auto refusal = [&](const std::string& line_2) {
    std::ofstream(path) << lines[0] << '\n' << line_2 << '\n' << lines[2] << '\n';
    try {
      Log().Reuse(path);
    } catch (const schema::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  std::string edited = lines[1];
  edited.replace(edited.find(",0.25,"), 6, ",0.26,");
  EXPECT_NE(refusal(edited).find("log.csv:2: the line does not match its checksum (edited?); cut line 2"), std::string::npos);
  std::string negative = lines[1];
  negative.replace(negative.find(",0.25,"), 6, ",-1,");
  EXPECT_NE(refusal(negative).find("log.csv:2: column '1.fixed.avg_m': -1 is not a finite number >= 0"), std::string::npos);
  std::string not_finite = lines[1];
  not_finite.replace(not_finite.find(",0.25,"), 6, ",inf,");
  EXPECT_NE(refusal(not_finite).find("inf is not a finite number >= 0"), std::string::npos);
  EXPECT_EQ(refusal(lines[1] + "\r"), "accepted");  // CRLF line ends are read as they are meant
  // The same point again, with other cells and a checksum made to fit: one of the two is wrong.
  EvaluationLog other = Log();
  other.Record(At("0.75", 0.9), false);
  std::string repeated = other.Line(0);
  repeated.replace(repeated.find(",0,global,"), 10, ",1,global,");
  repeated = repeated.substr(0, repeated.rfind(','));
  const std::string fingerprint = io::Fingerprint(repeated);
  repeated += ',';  // (not "," + ...: GCC 12's -Wrestrict false positive)
  repeated += fingerprint;
  EXPECT_NE(refusal(repeated).find("log.csv:3: the evaluation at these values has other cells than line 2"),
            std::string::npos);
}

// A log that cannot be written says why (here a device that is always full).
TEST_F(EvaluationLogTest, AFailedWriteSaysWhy) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  EvaluationLog log = Log();
  try {
    log.AppendTo("/dev/full");
    log.Record(At("0.5", 0.25), true);
    FAIL() << "writing to /dev/full succeeded";
  } catch (const schema::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full: writing the evaluation log failed: No space left on device"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace anchorbench::studies
