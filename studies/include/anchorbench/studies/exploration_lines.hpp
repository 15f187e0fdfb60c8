#pragma once
// An exploration's records as CSV lines at round-trip precision, and back: what explore's journal
// (record_journal.hpp) holds, so that a resumed run writes the uninterrupted run's bytes.

#include <string>
#include <vector>

#include "anchorbench/studies/exploration.hpp"

namespace anchorbench::studies {

// A (row, realization)'s records as the lines of a journal's unit, and back: refuses (InputError
// naming `source` and the line) lines that are not `row` and `realization`'s records of `policies`,
// each once, in order, or that hold what no run writes (a negative count, more certified than
// anchors).
std::string ExplorationUnitText(const std::vector<ExplorationRecord>& records);
std::vector<ExplorationRecord> ReadExplorationUnit(const std::string& text, const std::string& source, int row,
                                                   int realization, const std::vector<std::string>& policies);

}  // namespace anchorbench::studies
