#pragma once
// A PDOP study's realization (one unit) as CSV lines at round-trip precision, and back: what
// pdop-study's journal (record_journal.hpp) and its shards' records.csv hold, so that a resumed or
// merged study writes the uninterrupted run's bytes. One line per checkpoint, one per anchor's
// certified outcome, then the realization's PDOP statistics: each kind fills its own columns.

#include <string>
#include <vector>

#include "anchorbench/engine/record_journal.hpp"
#include "anchorbench/schema/pdop_study.hpp"

namespace anchorbench::studies {

// A realization's study (one record) as lines, and back: refuses (InputError naming `place`'s file
// and the line) lines of another realization, a kind no run writes, counts no run writes (a
// negative count, more samples below than samples), or a realization without its statistics line.
std::string PdopUnitText(const std::vector<schema::PdopStudy>& records);
std::vector<schema::PdopStudy> ReadPdopUnit(const std::string& text, const engine::UnitPlace& place, int realization);

}  // namespace anchorbench::studies
