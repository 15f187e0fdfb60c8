#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

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
schema::PdopStudy RunPdopStudy(const schema::ExperimentConfig& config, const registry::Components& components, int every, int threads,
                               const engine::RunControl& control = {});

}  // namespace anchorbench::studies
