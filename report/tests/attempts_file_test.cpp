// attempts.csv's lines read back (a resumed run's chunks, an MPI rank's): what the summaries use,
// and the line as written; and the paper's cells compared with ours.
#include "anchorbench/report/attempts_file.hpp"

#include <gtest/gtest.h>

#include "anchorbench/report/paper_cells.hpp"
#include "anchorbench/report/run_outputs.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::report {
namespace {

std::vector<schema::RowConfig> TwoRows() {
  std::vector<schema::RowConfig> rows(2);
  rows[0].name = "quiet";
  rows[1].name = "noisy";
  return rows;
}

std::vector<schema::Attempt> TwoAttempts() {
  schema::Attempt done;
  done.row = 1;
  done.realization = 4;
  done.anchor_id = 7;
  done.method = schema::kPaperTrigger;
  done.initialized = true;
  done.t_init_s = 12.5;
  done.n_used = 300;
  done.pdop_closest_point = 0.75;
  done.status = "converged";
  done.evaluation = schema::AttemptEvaluation{};
  done.evaluation->error_m = 0.125;
  done.evaluation->nees_position = 2.5;
  done.compute_s = 0.25;
  schema::Attempt waiting;
  waiting.row = 0;
  waiting.realization = 4;
  waiting.anchor_id = 8;
  waiting.method = schema::kFixedWindowTrigger;
  waiting.status = "not_triggered";
  waiting.compute_s = 0.5;
  return {done, waiting};
}

// A chunk's text: attempts.csv with compute_s last.
std::string ChunkLike(const std::vector<schema::Attempt>& attempts, const std::vector<schema::RowConfig>& rows) {
  std::string text = std::string(kAttemptsColumns) + ",compute_s\n";
  for (const schema::Attempt& a : attempts) text += AttemptLine(a, rows) + "," + std::to_string(a.compute_s) + "\n";
  return text;
}

TEST(AttemptsFile, ReadsBackWhatTheSummariesUseAndTheLineAsWritten) {
  const auto rows = TwoRows();
  const auto written = TwoAttempts();
  const AttemptsFile file = ParseAttempts(ChunkLike(written, rows), "chunk", rows);
  ASSERT_EQ(file.attempts.size(), 2u);
  EXPECT_EQ(file.lines, AttemptLine(written[0], rows) + "\n" + AttemptLine(written[1], rows) + "\n");  // compute_s cut off
  for (std::size_t i = 0; i < written.size(); ++i) {
    EXPECT_EQ(file.attempts[i].row, written[i].row);
    EXPECT_EQ(file.attempts[i].realization, written[i].realization);
    EXPECT_EQ(file.attempts[i].method, written[i].method);
    EXPECT_EQ(file.attempts[i].initialized, written[i].initialized);
    EXPECT_EQ(file.attempts[i].t_init_s, written[i].t_init_s);
    EXPECT_EQ(file.attempts[i].compute_s, written[i].compute_s);
  }
  ASSERT_TRUE(file.attempts[0].evaluation.has_value());
  EXPECT_EQ(file.attempts[0].evaluation->error_m, 0.125);
  EXPECT_EQ(file.attempts[0].evaluation->nees_position, 2.5);
  EXPECT_FALSE(file.attempts[1].evaluation && file.attempts[1].evaluation->error_m);
}

TEST(AttemptsFile, RefusesAnUnknownRowAMissingComputeColumnAndABadNumberNamingTheLine) {
  const auto rows = TwoRows();
  std::string text = ChunkLike(TwoAttempts(), rows);
  const std::string renamed = std::string(text).replace(text.find("noisy"), 5, "other");
  EXPECT_THROW(ParseAttempts(renamed, "chunk", rows), schema::InputError);
  try {
    ParseAttempts(std::string(kAttemptsColumns) + "\n" + AttemptLine(TwoAttempts()[0], rows) + "\n", "plain.csv", rows);
    ADD_FAILURE() << "a file without compute_s was read";
  } catch (const schema::InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("plain.csv:1:", 0), 0u) << e.what();
  }
  const std::string bad = std::string(text).replace(text.find("12.5"), 4, "12.x");
  try {
    ParseAttempts(bad, "chunk", rows);
    ADD_FAILURE() << "a bad number was read";
  } catch (const schema::InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("chunk:2:", 0), 0u) << e.what();
  }
}

TEST(PaperCells, WithinAQuarterNeedsOursAndAPaperZeroNeedsOursZero) {
  PaperCell cell;
  cell.paper = 0.2;
  EXPECT_FALSE(WithinQuarter(cell));  // nothing initialized: no match
  cell.ours = 0.25;
  EXPECT_TRUE(WithinQuarter(cell));
  cell.ours = 0.2501;
  EXPECT_FALSE(WithinQuarter(cell));
  cell.paper = 0.0;  // a zero cell (no failures): only zero matches it
  cell.ours = 0.0;
  EXPECT_TRUE(WithinQuarter(cell));
  cell.ours = 3.0;
  EXPECT_FALSE(WithinQuarter(cell));
  cell.lo = 0.5;
  cell.hi = 4.0;
  EXPECT_FALSE(PaperInsideInterval(cell));
  cell.paper = 0.5;
  EXPECT_TRUE(PaperInsideInterval(cell));
}

}  // namespace
}  // namespace anchorbench::report
