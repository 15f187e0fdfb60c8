#include "anchorbench/studies/objective.hpp"

#include <algorithm>
#include <cmath>

namespace anchorbench::studies {

using report::PaperColumn;

std::optional<double> LogRatio(const report::PaperCell& cell) {
  if (!cell.ours) return std::nullopt;
  const double floor = cell.column == PaperColumn::kInit || cell.column == PaperColumn::kGt1m ? 0.5
                       : cell.column == PaperColumn::kRatio                                 ? 0.1
                                                                                            : 0.0;
  return std::log((*cell.ours + floor) / (cell.paper + floor));
}

double CellCost(const report::PaperCell& cell, double band) {
  const std::optional<double> log_ratio = LogRatio(cell);
  if (!log_ratio) return kMissingCellCost;
  const double above = *log_ratio - std::log1p(band);   // > 0 above the band
  const double below = std::log1p(-band) - *log_ratio;  // > 0 below it
  const double outside = std::max({above, below, 0.0});
  return outside * outside;
}

double Objective(const std::vector<report::PaperCell>& cells, const schema::PaperCells& weight, bool held_out,
                 double band) {
  double sum = 0.0, weights = 0.0;
  for (const report::PaperCell& cell : cells) {
    const double w = report::ValueOf(weight, cell.column);
    const double used = held_out ? (w > 0.0 ? 0.0 : 1.0) : w;
    if (used <= 0.0) continue;
    sum += used * CellCost(cell, band);
    weights += used;
  }
  return weights > 0.0 ? sum / weights : 0.0;
}

}  // namespace anchorbench::studies
