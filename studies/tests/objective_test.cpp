#include "anchorbench/studies/objective.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace anchorbench::studies {
namespace {

using report::PaperCell;
using report::PaperColumn;

PaperCell Cell(PaperColumn column, double paper, std::optional<double> ours) {
  PaperCell cell;
  cell.column = column;
  cell.paper = paper;
  cell.ours = ours;
  return cell;
}

TEST(ObjectiveTest, LogRatioIsSymmetricAndFloorsZeroCounts) {
  EXPECT_NEAR(*LogRatio(Cell(PaperColumn::kAvg, 0.2, 0.4)), std::log(2.0), 1e-12);
  EXPECT_NEAR(*LogRatio(Cell(PaperColumn::kAvg, 0.2, 0.1)), -std::log(2.0), 1e-12);
  // Zero counts stay finite: half a count for Init and >1m, 0.1 % for Ratio.
  EXPECT_NEAR(*LogRatio(Cell(PaperColumn::kGt1m, 37, 0)), std::log(0.5 / 37.5), 1e-12);
  EXPECT_NEAR(*LogRatio(Cell(PaperColumn::kRatio, 2.71, 0)), std::log(0.1 / 2.81), 1e-12);
  EXPECT_FALSE(LogRatio(Cell(PaperColumn::kMed, 0.05, std::nullopt)));
}

TEST(ObjectiveTest, WeighsFittedColumnsAndHoldsOutTheRest) {
  const schema::PaperCells weight{1.0, 3.0, 0.0, 0.0, 0.0};  // Avg 1, Med 3, the rest held out
  const std::vector<PaperCell> cells{Cell(PaperColumn::kAvg, 1.0, std::exp(1.0)),
                                     Cell(PaperColumn::kMed, 1.0, std::exp(-2.0)),
                                     Cell(PaperColumn::kRatio, 10.0, std::nullopt)};
  EXPECT_NEAR(Objective(cells, weight), (1.0 * 1.0 + 3.0 * 4.0) / 4.0, 1e-12);
  // Held out: the Ratio cell alone, missing, costs a factor 10.
  EXPECT_NEAR(Objective(cells, weight, true), kMissingCellCost, 1e-12);
  EXPECT_NEAR(kMissingCellCost, std::pow(std::log(10.0), 2), 1e-12);
}

TEST(ObjectiveTest, ABandMakesCellsInsideItFree) {
  EXPECT_EQ(CellCost(Cell(PaperColumn::kAvg, 1.0, 1.2), 0.25), 0.0);
  EXPECT_EQ(CellCost(Cell(PaperColumn::kAvg, 1.0, 0.8), 0.25), 0.0);
  // Outside, the log-distance to the band's edge: 2 is ln(2 / 1.25) above it, 0.5 ln(0.75 / 0.5) below.
  EXPECT_NEAR(CellCost(Cell(PaperColumn::kAvg, 1.0, 2.0), 0.25), std::pow(std::log(2.0 / 1.25), 2), 1e-12);
  EXPECT_NEAR(CellCost(Cell(PaperColumn::kAvg, 1.0, 0.5), 0.25), std::pow(std::log(0.75 / 0.5), 2), 1e-12);
  EXPECT_NEAR(CellCost(Cell(PaperColumn::kAvg, 1.0, 2.0)), std::pow(std::log(2.0), 2), 1e-12);  // no band
}

TEST(ObjectiveTest, PerfectMatchCostsNothing) {
  const std::vector<PaperCell> cells{Cell(PaperColumn::kAvg, 0.233, 0.233), Cell(PaperColumn::kInit, 1362, 1362)};
  EXPECT_EQ(Objective(cells, schema::PaperCells{1, 1, 1, 0, 0}), 0.0);
}

}  // namespace
}  // namespace anchorbench::studies
