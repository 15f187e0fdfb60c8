#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "anchorbench/engine/commit.hpp"
#include "anchorbench/engine/run_control.hpp"
#include "anchorbench/registry/components.hpp"
#include "anchorbench/schema/experiment.hpp"
#include "anchorbench/schema/pdop_study.hpp"

namespace anchorbench::studies {

// Runs the config's base scenario for every realization through the online front end: each
// anchor's chain is the configured filter and a probe in the trigger's place, which sees every
// accepted sample and takes one checkpoint every `every` of them; a second chain, the configured
// estimator with the certified trigger, runs beside it. Both chains are built by
// registry::MakeInitializer (the probe through a TriggerMaker), parallel over realizations as a
// study of units (unit_records.hpp), identical for any thread count; `control` sees every
// realization done.
// Refuses (InputError) what the study cannot run: a checkpoint every `every` samples outside
// [1, 1e6], summary bins of `bin_s` outside [0.01, 120] s (Fig. 7's first 120 s, at most 12,000
// bins), more than 1e6 anchors over the realizations. `source` names the config in errors.
void CheckPdopStudy(const schema::ExperimentConfig& config, int every, double bin_s, const std::string& source);

schema::PdopStudy RunPdopStudy(const schema::ExperimentConfig& config, const registry::Components& components, int every, int threads,
                               const engine::RunControl& control = {});

// pdop_trace.csv (every checkpoint), pdop_study.md (the summary in `bin_s` bins) and
// manifest.json; returns the Markdown.
std::string WritePdopStudyFiles(const engine::FileWriter& write, const schema::ExperimentConfig& config,
                                const schema::PdopStudy& study, int every, double bin_s, const report::RunInfo& info);

}  // namespace anchorbench::studies
