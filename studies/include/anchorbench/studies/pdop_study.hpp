#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "anchorbench/engine/commit.hpp"
#include "anchorbench/engine/run_control.hpp"
#include "anchorbench/engine/unit_records.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/schema/experiment.hpp"
#include "anchorbench/schema/pdop_study.hpp"

namespace anchorbench::studies {

// The config's pdop_study settings, or their defaults where it has none.
schema::PdopStudyConfig PdopStudyOf(const schema::ExperimentConfig& config);

// Refuses (InputError) what the study cannot run: a filter no one registered, more than 1e6 anchors
// over the realizations (the config's pdop_study is checked where it is read).
void CheckPdopStudy(const schema::ExperimentConfig& config, const registry::Components& components);

// The study as units (unit_records.hpp), one per realization of the config's base scenario: each
// runs it through the online front end, where each anchor's chain is the configured filter and a
// probe in the trigger's place, which sees every accepted sample and takes one checkpoint every
// pdop_study.every of them; a second chain, the configured estimator with the certified trigger,
// runs beside it. Both chains are built by registry::MakeInitializer (the probe through a
// TriggerMaker). A unit's record is that realization's PdopStudy, its text pdop_lines.hpp's.
engine::UnitRecords<schema::PdopStudy> PdopStudyUnits(const schema::ExperimentConfig& config,
                                                      const registry::Components& components);

// Every unit on `threads` threads (engine::RunUnitRecords), in realization order: the same for
// any thread count; `control` sees every realization done.
std::vector<schema::PdopStudy> RunPdopStudy(const schema::ExperimentConfig& config,
                                            const registry::Components& components, int threads,
                                            const engine::RunControl& control = {});

// The realizations' records as one study, in their order.
schema::PdopStudy JoinPdopStudy(const std::vector<schema::PdopStudy>& realizations);

// pdop_trace.csv (every checkpoint), pdop_study.md (the summary in pdop_study.bin_s bins) and
// manifest.json, from the realizations' records in order; returns the Markdown.
std::string WritePdopStudyFiles(const engine::FileWriter& write, const schema::ExperimentConfig& config,
                                const std::vector<schema::PdopStudy>& realizations, const report::RunInfo& info);

}  // namespace anchorbench::studies
