#pragma once

#include <filesystem>
#include <map>
#include <ostream>
#include <span>

#include "anchorbench/eval/attempt_evaluation.hpp"
#include "anchorbench/io/recorded_data.hpp"
#include "anchorbench/sim/scenario.hpp"

namespace anchorbench::io {

// The interchange formats written (recorded_data.hpp reads them back): a header, then one row per
// record, numbers as the shortest text that reads back to the same double.
void WritePoses(std::ostream& out, std::span<const PoseRecord> poses);
void WriteRanges(std::ostream& out, std::span<const RangeRecord> ranges);
// The bias column appears when at least one anchor has a bias.
void WriteAnchors(std::ostream& out, const std::map<int, eval::AnchorTruth>& anchors);

// poses.csv, ranges.csv and anchors.csv into `folder` (created if needed), each file atomically.
void WriteRecordingFiles(const std::filesystem::path& folder, std::span<const PoseRecord> poses,
                         std::span<const RangeRecord> ranges, const std::map<int, eval::AnchorTruth>& anchors);

// Writes one realization as poses.csv (the *reported* tag positions, i.e. with sigma_position_m
// noise: what a robot's navigation would log), ranges.csv and anchors.csv (truth, with bias) into
// `folder`, each file atomically. The folder is created if needed.
void WriteScenarioFiles(const sim::Scenario& scenario, const std::filesystem::path& folder);

}  // namespace anchorbench::io
