#pragma once

#include <filesystem>

#include "anchorbench/sim/scenario.hpp"

namespace anchorbench::experiments {

// Writes one realization as poses.csv (the *reported* tag positions, i.e. with sigma_position_m
// noise: what a robot's navigation would log), ranges.csv and anchors.csv (truth, with bias) into
// `folder`, each file atomically. The folder is created if needed.
void WriteScenarioFiles(const sim::Scenario& scenario, const std::filesystem::path& folder);

}  // namespace anchorbench::experiments
