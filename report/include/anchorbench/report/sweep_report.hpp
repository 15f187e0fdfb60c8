#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "anchorbench/report/summary.hpp"
#include "anchorbench/schema/experiment.hpp"
#include "anchorbench/schema/sweep.hpp"

namespace anchorbench::report {

// The summaries of one grid point of a sweep.
struct SweepPointResult {
  schema::SweepPoint point;
  std::vector<schema::RowConfig> rows;
  std::vector<MethodSummary> summaries;
};

// sweep.csv: the axes' keys, then summary.csv's columns; one line per point, row and method.
void WriteSweepCsv(std::ostream& out, const std::vector<schema::SweepAxis>& axes,
                   const std::vector<SweepPointResult>& results);
// timing.csv beside it: the axes, then timing.csv's columns.
void WriteSweepTiming(std::ostream& out, const std::vector<schema::SweepAxis>& axes,
                      const std::vector<SweepPointResult>& results);
// sweep.md: the same as a table for people.
void WriteSweepMarkdown(std::ostream& out, const std::string& name, int realizations, std::uint64_t seed,
                        const std::vector<schema::SweepAxis>& axes, const std::vector<SweepPointResult>& results);

}  // namespace anchorbench::report
