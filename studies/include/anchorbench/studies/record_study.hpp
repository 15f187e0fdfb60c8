#pragma once
// The studies whose (row, realization) units each give records (navigate, explore, pdop-study), as one kind of
// study: what their command, its shards and the merge need of each, the same for all. A unit
// travels as its records' text (unit_records.hpp: the journal's and a shard's records.csv, at
// round-trip precision), so a resumed or merged run writes the uninterrupted run's bytes. A new
// such study is a UnitRecords of its own, a writer of its files, and one entry in RecordStudies().

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "anchorbench/engine/commit.hpp"
#include "anchorbench/engine/record_journal.hpp"
#include "anchorbench/engine/run_control.hpp"
#include "anchorbench/engine/shard.hpp"
#include "anchorbench/engine/unit_records.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/report/run_outputs.hpp"
#include "anchorbench/schema/experiment.hpp"

namespace anchorbench::studies {

struct RecordStudy {
  std::string command;  // "navigate": the command line's, shard.csv's
  // Refuses (InputError) a config the study cannot run, before any work.
  std::function<void(const schema::ExperimentConfig&, const registry::Components&)> check;
  // How many (row, realization) units the config has.
  std::function<int(const schema::ExperimentConfig&, const registry::Components&)> units;
  // About the size of its result files, for the result folder's free-space check.
  std::function<std::uintmax_t(const schema::ExperimentConfig&)> result_bytes;
  // The units `shard` holds as their texts (engine::RunUnitTexts, with the journal if any),
  // computed as `computing` says (its plan: the config's).
  std::function<std::map<int, std::string>(const schema::ExperimentConfig&, const registry::Components&,
                                           const engine::UnitComputing&, const engine::Shard&,
                                           const engine::RunControl&, engine::RecordJournal*)>
      run;
  // How a unit's text is computed (what an MPI worker rank computes, from the plan's config).
  std::function<std::function<std::string(int unit)>(const schema::ExperimentConfig&, const registry::Components&)>
      unit_text;
  // Its result files (and manifest.json) from every unit's text, through `write`; returns the
  // Markdown. A text that is not its unit's records is an InputError naming `place_of(unit)`.
  std::function<std::string(const engine::FileWriter&, const schema::ExperimentConfig&, const registry::Components&,
                            const std::map<int, std::string>& units, const std::function<engine::UnitPlace(int)>& place_of,
                            const report::RunInfo&)>
      write;
};

// navigate, explore and pdop-study.
const std::vector<RecordStudy>& RecordStudies();
// The study `command` names, or null.
const RecordStudy* FindRecordStudy(std::string_view command);

}  // namespace anchorbench::studies
