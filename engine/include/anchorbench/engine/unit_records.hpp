#pragma once
// A study whose (row, realization) units each give records (navigate, explore): the units computed
// on threads, each appended to the study's journal as it finishes, and those a killed run's journal
// kept taken back instead of computed again. The study says how one unit is computed, how its
// records are written into the journal and how they are read back; this file does the rest, the
// same way for every such study.

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "anchorbench/engine/executor.hpp"
#include "anchorbench/engine/record_journal.hpp"
#include "anchorbench/engine/run_control.hpp"
#include "anchorbench/engine/shard.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::engine {

template <typename Record>
struct UnitRecords {
  int units = 0;  // unit = row * realizations + realization
  std::function<std::vector<Record>(int unit)> compute;
  // With a journal only: a unit's records as whole lines, as the journal keeps them, and read back
  // (throws schema::InputError naming `source` where the text is not that unit's records).
  std::function<std::string(const std::vector<Record>&)> text;
  std::function<std::vector<Record>(const std::string& text, const std::string& source, int unit)> read;
};

// The units `shard` holds on `threads` threads (ParallelRecords), their records joined in unit
// order: the same for any thread count, whichever units came from the journal. With a journal, its
// units that read back are taken as they are (the rest refused in it, and computed again), and each
// unit computed is appended to it as it finishes. `control` sees the units computed now.
template <typename Record>
std::vector<Record> RunUnitRecords(const UnitRecords<Record>& study, int threads, const Shard& shard,
                                   const RunControl& control, RecordJournal* journal) {
  std::map<int, std::vector<Record>> finished;
  if (journal) {
    for (auto& [unit, text] : journal->TakeFinished()) {
      if (!shard.Holds(static_cast<int>(unit))) {
        journal->Refuse(unit, "not a unit of this shard");
        continue;
      }
      try {
        finished.emplace(static_cast<int>(unit), study.read(text, journal->folder().string(), static_cast<int>(unit)));
      } catch (const schema::InputError& e) {
        journal->Refuse(unit, e.what());
      }
    }
  }
  std::vector<int> missing;
  for (int unit = 0; unit < study.units; ++unit) {
    if (shard.Holds(unit) && finished.count(unit) == 0) missing.push_back(unit);
  }
  using UnitOfRecords = std::pair<int, std::vector<Record>>;
  std::vector<UnitOfRecords> computed = ParallelRecords<UnitOfRecords>(
      static_cast<int>(missing.size()), threads,
      [&](int i) {
        const int unit = missing[static_cast<std::size_t>(i)];
        std::vector<Record> records = study.compute(unit);
        if (journal) journal->Append(unit, study.text(records));
        return std::vector<UnitOfRecords>{{unit, std::move(records)}};
      },
      control);
  for (auto& [unit, records] : computed) finished.emplace(unit, std::move(records));
  std::vector<Record> records;
  for (auto& [unit, of_unit] : finished) {
    for (Record& r : of_unit) records.push_back(std::move(r));
  }
  return records;
}

}  // namespace anchorbench::engine
