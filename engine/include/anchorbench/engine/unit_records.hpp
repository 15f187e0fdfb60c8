#pragma once
// A study whose (row, realization) units each give records (navigate, explore, the PDOP study): the
// units computed on threads, each appended to the study's journal as it finishes, and those a
// killed run's journal kept taken back instead of computed again. The study says how one unit is
// computed, how its records are written as text (the journal's and a shard's) and read back; this
// file does the rest, the same way for every such study.

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "anchorbench/engine/executor.hpp"
#include "anchorbench/engine/plan.hpp"
#include "anchorbench/engine/record_journal.hpp"
#include "anchorbench/engine/run_control.hpp"
#include "anchorbench/engine/shard.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::engine {

template <typename Record>
struct UnitRecords {
  int units = 0;  // unit = row * realizations + realization
  std::function<std::vector<Record>(int unit)> compute;
  // With a journal or shards only: a unit's records as whole lines, as the journal keeps them, and
  // read back (throws schema::InputError naming `place` where the text is not that unit's records).
  std::function<std::string(const std::vector<Record>&)> text;
  std::function<std::vector<Record>(const std::string& text, const UnitPlace& place, int unit)> read;
};

// Where a study's units are computed: by `executor` (this process's threads, or an MPI job's
// ranks, which rebuild the study named `study` from `plan`), or with none on this process's
// threads; `threads` threads a process.
struct UnitComputing {
  Executor* executor = nullptr;
  std::string study;
  const Plan* plan = nullptr;
  int threads = 1;
};

// The units `shard` holds, computed as `computing` says, as their records' texts (study.text), by
// unit: the same for any thread or rank count, whichever units came from the journal. With a
// journal, its units that read back (study.read) are taken as they were kept (the rest refused in
// it, and computed again), and each unit computed is appended to it as it finishes. `control` sees
// the units computed now.
template <typename Record>
std::map<int, std::string> RunUnitTexts(const UnitRecords<Record>& study, const UnitComputing& computing,
                                        const Shard& shard, const RunControl& control, RecordJournal* journal) {
  std::map<int, std::string> texts;
  if (journal) {
    for (auto& [unit, text] : journal->TakeFinished()) {
      if (!shard.Holds(static_cast<int>(unit))) {
        journal->Refuse(journal->PlaceOf(unit).where() + ": unit " + std::to_string(unit) +
                        " is not a unit of this shard");
        continue;
      }
      try {
        study.read(text, journal->PlaceOf(unit), static_cast<int>(unit));
        texts.emplace(static_cast<int>(unit), std::move(text));
      } catch (const schema::InputError& e) {
        journal->Refuse(e.what());
      }
    }
  }
  std::vector<int> missing;
  for (int unit = 0; unit < study.units; ++unit) {
    if (shard.Holds(unit) && texts.count(unit) == 0) missing.push_back(unit);
  }
  const UnitWork work{computing.study, computing.plan,
                      [&study](int unit) { return study.text(study.compute(unit)); }};
  long long done = 0;
  const auto total = static_cast<long long>(missing.size());
  if (control.progress) control.progress(0, total);
  const UnitDone take = [&](int unit, std::string&& text) {  // one unit at a time
    if (journal) journal->Append(unit, text);
    texts.emplace(unit, std::move(text));
    if (control.progress) control.progress(++done, total);
  };
  if (computing.executor) {
    computing.executor->ComputeUnits(work, missing, computing.threads, take);
  } else {
    ComputeUnitsHere(work, missing, computing.threads, take, control.stop);
  }
  return texts;
}

// Every unit's records read back from its text (study.read, naming `place_of(unit)` where one is
// not that unit's records), joined in unit order.
template <typename Record>
std::vector<Record> ReadUnitTexts(const UnitRecords<Record>& study, const std::map<int, std::string>& texts,
                                  const std::function<UnitPlace(int unit)>& place_of) {
  std::vector<Record> records;
  for (const auto& [unit, text] : texts) {
    for (Record& r : study.read(text, place_of(unit), unit)) records.push_back(std::move(r));
  }
  return records;
}

// The records of the units `shard` holds, joined in unit order: the same for any thread count.
// With a journal, through the units' texts (RunUnitTexts), read back at round-trip precision: a
// resumed run gives the uninterrupted run's records. Without one, straight from study.compute.
template <typename Record>
std::vector<Record> RunUnitRecords(const UnitRecords<Record>& study, int threads, const Shard& shard,
                                   const RunControl& control, RecordJournal* journal) {
  if (journal) {
    return ReadUnitTexts(study, RunUnitTexts(study, UnitComputing{nullptr, {}, nullptr, threads}, shard, control, journal),
                         [journal](int unit) { return journal->PlaceOf(unit); });
  }
  std::vector<int> held;
  for (int unit = 0; unit < study.units; ++unit) {
    if (shard.Holds(unit)) held.push_back(unit);
  }
  return ParallelRecords<Record>(
      static_cast<int>(held.size()), threads, [&](int i) { return study.compute(held[static_cast<std::size_t>(i)]); },
      control);
}

}  // namespace anchorbench::engine
