#pragma once
// Our table against a published one, cell by cell: what summary.md's comparison and
// `anchorbench calibrate` both count.

#include <optional>
#include <string>
#include <vector>

#include "anchorbench/report/summary.hpp"
#include "anchorbench/schema/experiment.hpp"

namespace anchorbench::report {

// Table I's columns, in its order.
enum class PaperColumn { kAvg, kMed, kInit, kGt1m, kRatio };
constexpr PaperColumn kPaperColumns[] = {PaperColumn::kAvg, PaperColumn::kMed, PaperColumn::kInit, PaperColumn::kGt1m,
                                         PaperColumn::kRatio};
const char* ToString(PaperColumn column);  // "avg_m", "med_m", "init", "gt1m", "ratio_pct"
bool ParsePaperColumn(const std::string& name, PaperColumn* column);
// The column's entry of a value-per-column struct (the paper's cells, or a weight per column).
double ValueOf(const schema::PaperCells& cells, PaperColumn column);
// The decimals a table prints the column with: 3 (m), 0 (counts), 2 (%).
int Decimals(PaperColumn column);

struct PaperCell {
  int row = 0;         // index into the rows
  std::string method;  // schema::kFixedWindowTrigger or schema::kPaperTrigger
  PaperColumn column = PaperColumn::kAvg;
  double paper = 0.0;
  std::optional<double> ours;     // absent where nothing initialized
  std::optional<double> lo, hi;   // our 95% interval (Avg and Med when bootstrapped; Ratio)
  // Whether the cell counts in the score: Avg, Med, Init and Ratio (>1m is a count that follows
  // from Init and Ratio), except the fixed window's Init, which initializes every anchor with
  // data and so matches by construction.
  bool scored = false;
};

// The cells of every row that carries the paper's values and runs both of its methods, in table
// order (row, fixed before gated, columns as above), without ours.
std::vector<PaperCell> PaperTargets(const std::vector<schema::RowConfig>& rows);
// The same with ours filled in from the summaries of a run of those rows.
std::vector<PaperCell> CompareWithPaper(const std::vector<MethodSummary>& summaries,
                                        const std::vector<schema::RowConfig>& rows);

// Ours within +-25% of the paper's value (false when ours is absent).
bool WithinQuarter(const PaperCell& cell);
// The paper's value inside our 95% interval (false without one).
bool PaperInsideInterval(const PaperCell& cell);

struct PaperScore {
  int cells = 0;            // scored cells
  int within = 0;           // of those, within +-25%
  int with_interval = 0;    // Avg, Med and Ratio cells (ours have a 95% interval)
  int inside_interval = 0;  // of those, the paper's value inside our interval
};
PaperScore ScoreCells(const std::vector<PaperCell>& cells);

}  // namespace anchorbench::report
