#include "anchorbench/calibrate/evaluation_log.hpp"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "anchorbench/io/input_error.hpp"

namespace anchorbench::calibrate {
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
  EXPECT_EQ(header, "context,evaluation,stage,a.x,a.y,objective,1.fixed.avg_m,1.gated.init");
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
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("log.csv:1: the log is of other parameters or cells"), std::string::npos);
  }
}

}  // namespace
}  // namespace anchorbench::calibrate
