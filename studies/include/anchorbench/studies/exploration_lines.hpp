#pragma once
// An exploration's records as CSV lines at round-trip precision, and back: what explore's journal
// (record_journal.hpp) and its shards' records.csv hold, so that a resumed run writes the uninterrupted run's bytes.

#include <string>
#include <vector>

#include "anchorbench/engine/record_journal.hpp"
#include "anchorbench/studies/exploration.hpp"

namespace anchorbench::studies {

// A (row, realization)'s records as the lines of a journal's or a shard's unit, and back: refuses
// (InputError naming `place`'s file and the line) lines that are not `row` and `realization`'s records of `policies`,
// each once, in order, or that hold what no run writes (a negative count, more certified than
// anchors).
std::string ExplorationUnitText(const std::vector<ExplorationRecord>& records);
std::vector<ExplorationRecord> ReadExplorationUnit(const std::string& text, const engine::UnitPlace& place, int row,
                                                   int realization, const std::vector<std::string>& policies);

}  // namespace anchorbench::studies
