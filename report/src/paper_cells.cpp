#include "anchorbench/report/paper_cells.hpp"

#include <algorithm>
#include <cmath>

namespace anchorbench::report {

const char* ToString(PaperColumn column) {
  switch (column) {
    case PaperColumn::kAvg: return "avg_m";
    case PaperColumn::kMed: return "med_m";
    case PaperColumn::kInit: return "init";
    case PaperColumn::kGt1m: return "gt1m";
    case PaperColumn::kRatio: return "ratio_pct";
  }
  return "";
}

bool ParsePaperColumn(const std::string& name, PaperColumn* column) {
  for (PaperColumn c : kPaperColumns) {
    if (name == ToString(c)) {
      *column = c;
      return true;
    }
  }
  return false;
}

double ValueOf(const schema::PaperCells& paper, PaperColumn column) {
  switch (column) {
    case PaperColumn::kAvg: return paper.avg_m;
    case PaperColumn::kMed: return paper.med_m;
    case PaperColumn::kInit: return paper.init;
    case PaperColumn::kGt1m: return paper.gt1m;
    case PaperColumn::kRatio: return paper.ratio_pct;
  }
  return 0.0;
}

int Decimals(PaperColumn column) {
  return column == PaperColumn::kInit || column == PaperColumn::kGt1m ? 0 : column == PaperColumn::kRatio ? 2 : 3;
}

namespace {

// Ours into a target cell of the method's summary.
void Fill(const MethodSummary& s, PaperCell* cell) {
  switch (cell->column) {
    case PaperColumn::kAvg: cell->ours = s.avg_m, cell->lo = s.avg_lo, cell->hi = s.avg_hi; break;
    case PaperColumn::kMed: cell->ours = s.med_m, cell->lo = s.med_lo, cell->hi = s.med_hi; break;
    case PaperColumn::kInit: cell->ours = s.init; break;
    case PaperColumn::kGt1m: cell->ours = s.gt1m; break;
    case PaperColumn::kRatio: cell->ours = s.ratio_pct, cell->lo = s.ratio_lo, cell->hi = s.ratio_hi; break;
  }
}

bool Runs(const schema::RowConfig& row, const char* trigger) {
  return std::find(row.estimator.triggers.begin(), row.estimator.triggers.end(), trigger) != row.estimator.triggers.end();
}

}  // namespace

std::vector<PaperCell> PaperTargets(const std::vector<schema::RowConfig>& rows) {
  std::vector<PaperCell> cells;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (!rows[r].paper || !Runs(rows[r], schema::kFixedWindowTrigger) || !Runs(rows[r], schema::kPaperTrigger)) continue;
    for (const char* method : {schema::kFixedWindowTrigger, schema::kPaperTrigger}) {
      for (PaperColumn column : kPaperColumns) {
        PaperCell cell;
        cell.row = static_cast<int>(r);
        cell.method = method;
        cell.column = column;
        cell.paper = ValueOf(*rows[r].paper->For(method), column);
        cell.scored = column != PaperColumn::kGt1m &&
                      !(column == PaperColumn::kInit && cell.method == schema::kFixedWindowTrigger);
        cells.push_back(std::move(cell));
      }
    }
  }
  return cells;
}

std::vector<PaperCell> CompareWithPaper(const std::vector<MethodSummary>& summaries,
                                        const std::vector<schema::RowConfig>& rows) {
  std::vector<PaperCell> cells = PaperTargets(rows);
  for (PaperCell& cell : cells) {
    for (const MethodSummary& s : summaries) {
      if (s.row == cell.row && s.method == cell.method) Fill(s, &cell);
    }
  }
  return cells;
}

bool WithinQuarter(const PaperCell& cell) {
  if (!cell.ours) return false;
  if (cell.paper == 0.0) return *cell.ours == 0.0;  // no relative distance to zero: only zero matches
  return std::abs((*cell.ours - cell.paper) / cell.paper) <= 0.25 + 1e-12;
}

bool PaperInsideInterval(const PaperCell& cell) {
  return cell.lo && cell.hi && cell.paper >= *cell.lo - 1e-12 && cell.paper <= *cell.hi + 1e-12;
}

PaperScore ScoreCells(const std::vector<PaperCell>& cells) {
  PaperScore score;
  for (const PaperCell& cell : cells) {
    if (cell.scored) {
      ++score.cells;
      score.within += WithinQuarter(cell);
    }
    if (cell.column != PaperColumn::kInit && cell.column != PaperColumn::kGt1m) {
      ++score.with_interval;
      score.inside_interval += PaperInsideInterval(cell);
    }
  }
  return score;
}

}  // namespace anchorbench::report
