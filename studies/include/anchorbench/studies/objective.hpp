#pragma once
// What `anchorbench calibrate` minimizes: how far our cells are from the paper's, on a log scale
// so that a factor 2 too high and a factor 2 too low cost the same, whatever the column's unit.

#include <optional>
#include <vector>

#include "anchorbench/report/paper_cells.hpp"
#include "anchorbench/schema/experiment.hpp"

namespace anchorbench::studies {

// ln((ours + f) / (paper + f)), absent where ours is. The floor f keeps zero counts finite
// (our choice): 0.5 for Init and >1m (half a count), 0.1 for Ratio (%), 0 for Avg and Med (in m;
// both are > 0 wherever they exist).
std::optional<double> LogRatio(const report::PaperCell& cell);

// The cost of a cell that has no value of ours (nothing initialized): as if a factor 10 off.
constexpr double kMissingCellCost = 5.301898110478399;  // ln(10)^2

// A cell's cost: its squared log-ratio, or with a band > 0 the squared log-distance to the band
// [(1 - band) paper, (1 + band) paper], 0 inside it; kMissingCellCost without a value of ours.
double CellCost(const report::PaperCell& cell, double band = 0.0);

// The weighted mean of the cells' costs over the cells whose column has weight > 0:
// sum w cost / sum w. With band 0, exp(sqrt(objective)) is the typical factor ours is off by.
// With `held_out` the cells whose weight is 0, each weighing 1 (how well the fit predicts them).
double Objective(const std::vector<report::PaperCell>& cells, const schema::PaperCells& weight, bool held_out = false,
                 double band = 0.0);

}  // namespace anchorbench::studies
